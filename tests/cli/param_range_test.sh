#!/usr/bin/env bash
# A parameter's declared range (`param d: int = 6 in 1..10;`, docs/language.md
# §5.2): the interpreter and a compiled program accept the bounds, refuse a
# value outside them with the same message (writing nothing), and list the
# range in --help.
# Usage: param_range_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"

first_error() { [ "$(head -1 err.txt)" = "$1" ] || fail "wanted: $1 -- got: $(head -3 err.txt)"; }

cat > ranged.g2d <<'G2D'
const top = 10;
param depth: int = 6 in 1..top;
param tilt: float = 0.5 in 0..1 step 0.05;
param free: float = 3;
node Dot { style { r = 0.2; } }
axiom { a: Dot at (depth, tilt); b: Dot at (free, 0); }
G2D
expect_code 0 "$g2d" build ranged.g2d -o ranged_exe

for run in "$g2d run ranged.g2d" "./ranged_exe"; do
  name=$([ "$run" = ./ranged_exe ] && echo ranged_exe || echo "g2d run")
  # The bounds are inside the range; the outputs match the interpreter's.
  expect_code 0 $run -D depth=10 -D tilt=0 -D free=-40 -o "edge_$name.svg"
  expect_code 0 $run -D depth=1 -D tilt=1 --no-svg
  expect_code 2 $run -D depth=12 -o out.svg
  first_error "$name: error: parameter \`depth\` must be from 1 to 10 (the range its declaration gives), not 12"
  [ -e out.svg ] && fail "$name wrote out.svg after refusing a value"
  expect_code 2 $run -D tilt=-0.1 -o out.svg
  first_error "$name: error: parameter \`tilt\` must be from 0 to 1 (the range its declaration gives), not -0.1"
  expect_code 2 $run -D depth=6.5 --no-svg
  first_error "$name: error: parameter \`depth\`: expected an int, got \`6.5\`"
  expect_code 0 $run --help
  grep -qx '  depth: int  *default 6, from 1 to 10' out.txt || fail "$name --help: no depth range: $(cat out.txt)"
  grep -qx '  tilt: float  *default 0.5, from 0 to 1 in steps of 0.05' out.txt || fail "$name --help: no tilt range: $(cat out.txt)"
  grep -qx '  free: float  *default 3' out.txt || fail "$name --help: free: $(cat out.txt)"
done
cmp -s "edge_g2d run.svg" edge_ranged_exe.svg || fail "interpreted and compiled SVGs differ at the range's edges"

finish
