#!/usr/bin/env bash
# `g2d build` and `g2d emit-cpp`: failures are reported clearly, and compiled
# programs take g2d run's options and report errors the same way.
# Usage: build_command_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"
koch="$src/examples/koch_snowflake.g2d"

expect_code 1 "$g2d" build "$koch" -o k --cxx no-such-compiler
grep -q 'no C++ compiler `no-such-compiler` found' err.txt || fail "missing compiler message: $(cat err.txt)"
expect_code 1 "$g2d" build "$koch" -o k --cxx /bin/false
grep -q 'the C++ compiler failed (/bin/false, exit status 1); the generated code is kept at `k.cpp`' err.txt \
  || fail "compiler failure message: $(cat err.txt)"
[ -s k.cpp ] || fail "the generated code was not kept"
[ -e k ] && fail "a failed build left an executable"
expect_code 2 "$g2d" build "$koch" -o k -O 9
expect_code 1 "$g2d" build "$koch" -o /nonexistent/dir/k
printf 'node P;\naxiom { a: Q; }\n' > bad.g2d
expect_code 1 "$g2d" build bad.g2d -o bad
grep -q 'bad.g2d:2:12: error: unknown node kind `Q`' err.txt || fail "grammar errors: $(cat err.txt)"
expect_code 2 "$g2d" emit-cpp "$koch"

# A compiled program: options, usage errors, run-time errors like g2d run.
cat > div.g2d <<'G'
param d: float = 0;
node P;
axiom { p: P at (0, 0); }
rule R { match { p: P; } produce { p at (1 / d, 0); } }
G
expect_code 0 "$g2d" build div.g2d -o div --keep-cpp div.cpp
[ -s div.cpp ] || fail "--keep-cpp wrote nothing"
expect_code 1 ./div -o x.svg
cp err.txt compiled.txt
expect_code 1 "$g2d" run div.g2d -o x.svg
cmp -s err.txt compiled.txt || fail "error messages differ: $(cat err.txt) // $(cat compiled.txt)"
grep -q '^div.g2d:4:42: error: division by zero (in rule `R`, step 1)$' compiled.txt || fail "compiled error: $(cat compiled.txt)"
[ -e x.svg ] && fail "a failed compiled run wrote x.svg"
expect_code 0 ./div -D d=2 --steps 3 --stats --no-svg
grep -q '"steps": 3,' out.txt || fail "compiled --steps/--stats: $(cat out.txt)"
expect_code 2 ./div -D nosuch=1
# Bounds and --keep-partial as in g2d run: the same bytes for the last completed step
expect_code 1 ./div -D d=2 -o ci.svg --json ci.json --keep-partial
expect_code 1 "$g2d" run div.g2d -D d=2 -o ri.svg --json ri.json --keep-partial
cmp -s ci.svg ri.svg && cmp -s ci.json ri.json || fail "--keep-partial outputs differ (compiled vs interpreted)"
grep -q '"stopped": "default_step_limit"' ci.json || fail "compiled default limit: $(head -c 300 ci.json)"
expect_code 1 ./div -D d=2 --steps 1000000000 --timeout 0.2 --no-svg
grep -q 'ran past the time limit of 0.2 s at step' err.txt || fail "compiled --timeout: $(cat err.txt)"
expect_code 2 ./div --timeout -3
expect_code 2 ./div --frobnicate
expect_code 0 ./div --help

finish
