#!/usr/bin/env bash
# The engine-only embedding program (engine_only_test.cpp) checks what it
# reads through the API, and writes what it derived; its SVG, JSON and OBJ
# (and MTL, named as g2d run names it) must equal g2d run's byte for byte (the one output assembly both use).
# Usage: engine_only_test.sh PROGRAM G2D SOURCE_DIR
set -eu
program="$1"; g2d="$2"; src="$3"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
"$program" "$work"
"$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=2 --seed 7 -o "$work/koch.run.svg" --json "$work/koch.run.json" --obj "$work/koch.run.obj"
"$g2d" run "$src/examples/g3_box.g2d" --seed 3 -o "$work/box.run.svg" --json "$work/box.run.json" --obj "$work/box.run.obj"
for name in koch box; do
  for ext in svg json obj mtl; do
    cmp "$work/$name.$ext" "$work/$name.run.$ext"
  done
done
echo "1 passed, 0 failed"
