#!/usr/bin/env bash
# Sets everything up, builds g2d and derives the bundled Koch snowflake to
# out/koch_snowflake.svg (and the tree to out/tree.svg).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh release g2d   # the program only: the test command builds the tests
mkdir -p out
./build/release/bin/g2d run examples/koch_snowflake.g2d -o out/koch_snowflake.svg --json out/koch_snowflake.json --stats
./build/release/bin/g2d run examples/tree.g2d -o out/tree.svg --seed 7 --stats
echo "wrote out/koch_snowflake.svg, out/koch_snowflake.json and out/tree.svg"
