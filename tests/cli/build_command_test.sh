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
grep -q '^div: error: .*frobnicate' err.txt || fail "a compiled program names itself: $(cat err.txt)"
expect_code 2 ./div -D nosuch=1
grep -qx 'div: error: the grammar has no parameter `nosuch` (its parameters: d)' err.txt || fail "compiled -D error: $(cat err.txt)"
expect_code 2 ./div --seed -1
expect_code 0 ./div --help
grep -q '^  d: float  *default 0$' out.txt || fail "compiled --help lists no parameters: $(cat out.txt)"
for option in --max-elements --timeout --keep-partial --trace --trace-json --verify-matches; do
  grep -q -- "$option" out.txt || fail "compiled --help lacks $option"
done
expect_code 0 ./div -D " d = 2 " --steps 3 --stats --no-svg --verify-matches

# A literal style value is one constant of the generated grammar, copied by
# every element it is set on; computed ones are evaluated per rewrite. The
# compiled program draws the same bytes as the interpreter.
cat > lit.g2d <<'G'
node P { style { tag = "circle"; } }
edge L { style { stroke = "black"; } }
axiom { a: P at (0, 0); }
rule R {
    match { a: P; }
    produce {
        a;
        b: P at a.pos + (1, 0) { style.tag = "none", style.r = 0.5 };
        c: P at a.pos + (0, 1) { style.tag = "none", style.r = a.pos.x + 0.5 };
        a -[L { style.stroke = "none", style.stroke_width = 0.5 }]- b;
    }
}
G
expect_code 0 "$g2d" emit-cpp lit.g2d -o lit.cpp
[ "$(grep -c '^ *const Value kValue[0-9]*{std::string("none", 4)};$' lit.cpp)" = 1 ] || fail "the literal \"none\" is not one constant: $(grep -n 'none' lit.cpp)"
[ "$(grep -c '^ *const Value kValue[0-9]*{0.5};$' lit.cpp)" = 1 ] || fail "the literal 0.5 is not one constant: $(grep -n '0\.5' lit.cpp)"
grep -q 'std::string("none", 4)' <(grep -v '^ *const Value' lit.cpp) && fail "\"none\" is still built per rewrite"
[ "$(grep -c 'Style(h[0-9]*, StyleProp([0-9]* /\* tag \*/), kValue' lit.cpp)" = 2 ] || fail "tag not set from the constant: $(grep -n 'StyleProp' lit.cpp)"
grep -q 'StyleProp([0-9]* /\* r \*/), Value{r[0-9]' lit.cpp || fail "a computed style is not kept per rewrite: $(grep -n 'StyleProp' lit.cpp)"
expect_code 0 "$g2d" build lit.g2d -o lit
expect_code 0 ./lit --steps 3 -o lc.svg --json lc.json
expect_code 0 "$g2d" run lit.g2d --steps 3 -o li.svg --json li.json
cmp -s lc.svg li.svg && cmp -s lc.json li.json || fail "literal styles: compiled and interpreted outputs differ"
grep -q 'stroke-width="0.5"' lc.svg || fail "the edge's literal stroke width is missing: $(cat lc.svg)"

# The pick lookahead asks for a likely next rewrite's attribute records: the
# generated grammar names, per rule, those of its matched elements (Koch's
# split reads its edge's `lod`; its nodes have no attributes).
expect_code 0 "$g2d" emit-cpp "$koch" -o koch.cpp
grep -A4 'void prefetchData(std::size_t rule, Match m, const Graph& g) const override' koch.cpp \
  | grep -q '^ *store_[0-9]*\.prefetch(g\.edgeSlot(m\.edges\[0\]));$' || fail "no attribute prefetch for Koch's edge: $(grep -n -A6 'prefetchData' koch.cpp)"
grep -q 'prefetch(g\.nodeSlot' koch.cpp && fail "a prefetch for a node kind without attributes"

finish
