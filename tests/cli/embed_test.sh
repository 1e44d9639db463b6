#!/usr/bin/env bash
# cmake --install, then examples/embed (find_package(g2d), g2d_add_grammar)
# builds against the installed tree, runs, and matches `g2d run` byte for byte.
# Usage: embed_test.sh BUILD_DIR SOURCE_DIR
set -eu
build="$1"; src="$2"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$src/examples/embed" -B "$work/embed" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/embed" >/dev/null
"$work/embed/embed_demo" "$work/e.svg" "$work/e.json"
"$work/prefix/bin/g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=3 --seed 7 -o "$work/r.svg" --json "$work/r.json"
cmp "$work/e.svg" "$work/r.svg"
cmp "$work/e.json" "$work/r.json"
# An installed g2d builds programs from its own tree too.
(cd "$work" && "$work/prefix/bin/g2d" build "$src/examples/tree.g2d" -o "$work/tree" && "$work/tree" --no-svg --stats)
echo "1 passed, 0 failed"
