#!/usr/bin/env bash
# `g2d run` end to end: outputs, determinism, errors and exit codes.
# Usage: run_command_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"

# Outputs and stats
expect_code 0 "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=2 -o k.svg --json k.json --stats --seed 9
grep -qx '{"steps": 15, "nodes": 48, "edges": 48, "faces": 0, "seconds": [0-9.e-]*, "seed": 9, "stopped": "terminal", "applications": 15, "lookahead_guesses": 0, "lookahead_hits": 0, "repairs": 15, "repairs_skipped": 0, "rejected_drawings": 0, "rejected_by_cost": 0, "rejected_splits": 0, "bends_reduced": 0, "faces_against_neighbours": 0, "inserts_without_side": 0, "compounds_without_instances": 0, "rejected_intersections": 0}' out.txt \
  || fail "stats line: $(cat out.txt)"
head -c 38 k.svg | grep -q '<?xml version="1.0" encoding="UTF-8"?>' || fail "SVG header"
[ "$(grep -c '<line ' k.svg)" = 48 ] || fail "48 lines expected in k.svg"
grep -q '"directed": true, "multigraph": true' k.json || fail "node-link JSON header"
xmllint --noout k.svg || fail "SVG is not well-formed"
# NetworkX (Debian's python3-networkx) reads the JSON as a directed multigraph.
/usr/bin/python3 - k.json <<'PY' || fail "networkx.node_link_graph cannot read k.json"
import json, sys
import networkx as nx
g = nx.node_link_graph(json.load(open(sys.argv[1])))
assert g.is_directed() and g.is_multigraph()
assert g.number_of_nodes() == 48 and g.number_of_edges() == 48
node = g.nodes[0]
assert node["kind"] == "Point" and node["pos"] == [-4, 0] and node["age"] == 0
assert all(d["kind"] == "Seg" and d["directed"] and d["lod"] == 2 for _, _, d in g.edges(data=True))
PY

# -D tolerates spaces round the name and the value
expect_code 0 "$g2d" run "$src/examples/koch_snowflake.g2d" -D " max_lod = 2 " --no-svg --stats
grep -q '"steps": 15,' out.txt || fail "-D with spaces: $(cat out.txt) $(cat err.txt)"
expect_code 2 "$g2d" run "$src/examples/koch_snowflake.g2d" -D "gens = 3" --no-svg
grep -qx 'g2d run: error: the grammar has no parameter `gens` (its parameters: max_lod)' err.txt || fail "-D unknown: $(cat err.txt)"
# `g2d run FILE --help` lists the grammar's parameters, with types and defaults
expect_code 0 "$g2d" run "$src/examples/koch_snowflake.g2d" --help
grep -q -- '--verify-matches' out.txt || fail "run --help: $(cat out.txt)"
grep -q '^Parameters of the grammar (-D NAME=VALUE):$' out.txt && grep -q '^  max_lod: int  *default 4$' out.txt \
  || fail "run FILE --help lists no parameters: $(cat out.txt)"

# --verify-matches: the same outputs, checked after every step
expect_code 0 "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=3 -o v1.svg --verify-matches
expect_code 0 "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=3 -o v2.svg
cmp -s v1.svg v2.svg || fail "--verify-matches changed the output"

# Default output name: the grammar's name in the current folder
expect_code 0 "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=1
[ -f koch_snowflake.svg ] || fail "default output koch_snowflake.svg missing"

# Byte-identical for the same seed, different for another
"$g2d" run "$src/examples/tree.g2d" --seed 4 -o t1.svg --json t1.json >/dev/null 2>&1
"$g2d" run "$src/examples/tree.g2d" --seed 4 -o t2.svg --json t2.json >/dev/null 2>&1
"$g2d" run "$src/examples/tree.g2d" --seed 5 -o t3.svg >/dev/null 2>&1
cmp -s t1.svg t2.svg || fail "same seed, different SVG"
cmp -s t1.json t2.json || fail "same seed, different JSON"
cmp -s t1.svg t3.svg && fail "different seeds, same SVG"

# A run-time error: located message, exit 1, no output written, old file untouched
cat > div.g2d <<'G'
node P { d: float = 0; }
axiom { p: P at (0, 0); }
rule R { match { p: P; } produce { p at (1 / p.d, 0); } }
G
echo old > keep.svg
expect_code 1 "$g2d" run div.g2d -o keep.svg --json new.json
grep -q '^div.g2d:3:42: error: division by zero (in rule `R`, step 1)$' err.txt || fail "runtime error text: $(cat err.txt)"
[ "$(cat keep.svg)" = old ] || fail "a failed run overwrote keep.svg"
[ -e new.json ] && fail "a failed run left new.json"
ls | grep -q '\.tmp-' && fail "temporary files left behind"

# Unwritable outputs fail before the derivation, with exit 1
expect_code 1 "$g2d" run "$src/examples/koch_snowflake.g2d" -o /nonexistent/dir/x.svg
grep -q "cannot write \`/nonexistent/dir/x.svg\`" err.txt || fail "unwritable output message: $(cat err.txt)"
mkdir adir
expect_code 1 "$g2d" run "$src/examples/koch_snowflake.g2d" -o adir
grep -q "it is a directory" err.txt || fail "directory output message: $(cat err.txt)"

# Bad arguments exit 2
expect_code 2 "$g2d" run "$src/examples/koch_snowflake.g2d" -D nosuch=3
grep -q 'no parameter `nosuch` (its parameters: max_lod)' err.txt || fail "unknown parameter message: $(cat err.txt)"
expect_code 2 "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=abc
grep -qx 'g2d run: error: parameter `max_lod`: expected an int, got `abc`' err.txt || fail "bad value message: $(cat err.txt)"
# -D takes vec2, enum and bool values as the language writes them (and the short forms).
cat > params.g2d <<'G2D'
enum Mode { Big, Small }
param m: Mode = Big;
param v: vec2 = (0, 0);
param b: bool = false;
node P { big: bool = false; }
axiom { a: P at v { big = b and m == Mode.Small }; }
G2D
for vec in "(1.5,-2)" "1.5,-2" "( 1.5 , -2 )"; do
  for mode in Mode.Small Small; do
    args="-D m=$mode -D v=$vec -D b=true"
    expect_code 0 "$g2d" run params.g2d -D "m=$mode" -D "v=$vec" -D b=true --no-svg --json p.json
  python3 -c "import json; n = json.load(open('p.json'))['nodes'][0]; assert n['pos'] == [1.5, -2] and n['big'] is True, n" \
    || fail "-D $args: $(cat p.json)"
  done
done
expect_code 2 "$g2d" run params.g2d -D m=Colour.Small --no-svg
grep -qx 'g2d run: error: parameter `m`: expected a Mode, got `Colour.Small` (one of Big Small)' err.txt || fail "-D wrong enum: $(cat err.txt)"
expect_code 2 "$g2d" run params.g2d -D b=1 --no-svg
grep -qx 'g2d run: error: parameter `b`: expected a bool, got `1` (write true or false)' err.txt || fail "-D bad bool: $(cat err.txt)"
expect_code 2 "$g2d" run "$src/examples/koch_snowflake.g2d" --seed -1
expect_code 2 "$g2d" run

# Grammar errors exit 1 with diagnostics
printf 'node P;\naxiom { a: Q; }\n' > bad.g2d
expect_code 1 "$g2d" run bad.g2d
grep -q '^bad.g2d:2:12: error: unknown node kind `Q`' err.txt || fail "grammar error text: $(cat err.txt)"

# --steps overrides the limit; the default limit (no `limit`, no --steps) is
# a runaway guard: an error, and no output unless --keep-partial
printf 'node P;\naxiom { p: P at (0, 0); }\nrule Spin { match { p: P; } produce { p; } }\n' > spin.g2d
expect_code 0 "$g2d" run spin.g2d --steps 7 --stats --no-svg
grep -q '"steps": 7,.*"stopped": "step_limit"' out.txt || fail "--steps: $(cat out.txt)"
expect_code 1 "$g2d" run spin.g2d -o spin.svg
grep -qx 'spin.g2d: error: stopped at the default limit of 10000 steps: the grammar may not terminate (set `limit N;` or pass --steps N; --keep-partial writes the graph so far)' err.txt \
  || fail "default limit error: $(cat err.txt)"
[ -e spin.svg ] && fail "the default limit left an output"
expect_code 1 "$g2d" run spin.g2d -o spin.svg --json spin.json --keep-partial
grep -q '"steps": 10000' spin.json && grep -q '"stopped": "default_step_limit"' spin.json || fail "--keep-partial at the default limit: $(head -c 300 spin.json)"
grep -q 'note: wrote the graph of step 10000, the last completed (--keep-partial)' err.txt || fail "keep-partial note: $(cat err.txt)"
xmllint --noout spin.svg || fail "partial SVG is not well-formed"
# --stats after a bound reports the completed steps, not zeros
expect_code 1 "$g2d" run spin.g2d --no-svg --keep-partial --stats
grep -qx '{"steps": 10000, "nodes": 1, "edges": 0, "faces": 0, "seconds": [0-9.e-]*, "seed": 1, "stopped": "default_step_limit", "applications": 10000, "lookahead_guesses": 0, "lookahead_hits": 0, "repairs": 0, "repairs_skipped": 0, "rejected_drawings": 0, "rejected_by_cost": 0, "rejected_splits": 0, "bends_reduced": 0, "faces_against_neighbours": 0, "inserts_without_side": 0, "compounds_without_instances": 0, "rejected_intersections": 0}' out.txt \
  || fail "--stats at the default limit: $(cat out.txt)"
grep -q '"seconds": 0,' out.txt && fail "--stats at the default limit: no time: $(cat out.txt)"
expect_code 1 "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=20 --max-elements 1000 --no-svg --keep-partial --stats
grep -qx '{"steps": 166, "nodes": 501, "edges": 501, "faces": 0, "seconds": [0-9.e-]*, "seed": 1, "stopped": "element_limit", "applications": 166, "lookahead_guesses": 0, "lookahead_hits": 0, "repairs": 166, "repairs_skipped": 0, "rejected_drawings": 0, "rejected_by_cost": 0, "rejected_splits": 0, "bends_reduced": 0, "faces_against_neighbours": 0, "inserts_without_side": 0, "compounds_without_instances": 0, "rejected_intersections": 0}' out.txt \
  || fail "--stats at the element bound: $(cat out.txt)"

# --timeout: a wall-time bound with the step it tripped at; a usage error unless positive
expect_code 1 "$g2d" run spin.g2d --steps 1000000000 --timeout 0.2 -o slow.svg
grep -q '^spin.g2d: error: the derivation ran past the time limit of 0.2 s at step [0-9]* (raise --timeout)$' err.txt \
  || fail "--timeout: $(cat err.txt)"
[ -e slow.svg ] && fail "--timeout left an output"
expect_code 1 "$g2d" run spin.g2d --steps 1000000000 --timeout 0.2 -o slow.svg --json slow.json --keep-partial
grep -q '"stopped": "time_limit"' slow.json || fail "--timeout --keep-partial: $(head -c 300 slow.json)"
[ -e slow.svg ] || fail "--timeout --keep-partial wrote no SVG"
expect_code 1 "$g2d" run spin.g2d --steps 1000000000 --timeout 0.2 --no-svg --keep-partial --stats
python3 - out.txt <<'PY' || fail "--stats at the time bound: $(cat out.txt)"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["stopped"] == "time_limit" and s["steps"] > 0 and s["applications"] == s["steps"], s
assert s["seconds"] >= 0.2, s
PY
for bad in 0 -1 nan abc; do
  expect_code 2 "$g2d" run spin.g2d --timeout "$bad" --no-svg
done
expect_code 0 "$g2d" run spin.g2d --steps 100 --timeout 60 --no-svg
# A chain of N functions, each calling the previous twice: f_N costs 2^N calls.
chain() {
  echo "fn f0(x: int) -> int = x;"
  for i in $(seq 1 "$1"); do echo "fn f$i(x: int) -> int = f$((i - 1))(x) + f$((i - 1))(x) - x;"; done
}
# ... even inside a step that never finishes (2^59 function calls from step 4 on)
{ echo "node P { n: int = 0; }"; chain 59
  echo "axiom { a: P at (0, 0); }"; echo "limit 20;"
  echo "rule R { match { p: P; } produce { p at (p.n > 2 ? f59(1) : 0, 0) { n = p.n + 1 }; } }"; } > expo.g2d
# (2 s, not less: steps 1-3 take microseconds, but a loaded machine may
# leave the process unscheduled for a while, and the bound must still trip
# inside step 4.)
expect_code 1 "$g2d" run expo.g2d --timeout 2 -o expo.svg --json expo.json --keep-partial
grep -q '^expo.g2d: error: the derivation ran past the time limit of 2 s at step 4 (raise --timeout)$' err.txt || fail "timeout inside a step: $(cat err.txt)"
grep -q '"steps": 3, "stopped": "time_limit"' expo.json || fail "timeout inside a step, partial output: $(head -c 300 expo.json)"
# ... and inside --verify-matches' full search, which runs every condition again:
# Slow's (2^20 calls, never true) costs nothing in a step's update, as Tick
# changes only q, but all of the search; the bound trips there.
{ echo "node P { n: int = 0; }"; echo "node Q { n: int = 0; }"; chain 20
  echo "axiom { a: P at (0, 0); b: P at (1, 0); q: Q at (2, 0); }"
  echo "rule Slow { match { p: P where f20(p.n) != p.n; } produce { p; } }"
  echo "rule Tick { match { q: Q; } produce { q { n = q.n + 1 }; } }"; } > verify.g2d
expect_code 1 "$g2d" run verify.g2d --steps 1000000 --timeout 0.6 --verify-matches -o verify.svg
grep -q '^verify.g2d: error: the derivation ran past the time limit of 0.6 s at step [0-9]* (raise --timeout)$' err.txt \
  || fail "timeout inside --verify-matches: $(cat err.txt)"

# --max-elements: the runaway guard, with the step it tripped at; 0 is a usage error
expect_code 1 "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=6 --max-elements 1000 -o guard.svg
grep -q 'the graph grew past 1000 elements at step .*--max-elements' err.txt || fail "--max-elements: $(cat err.txt)"
[ -e guard.svg ] && fail "--max-elements left an output"
expect_code 2 "$g2d" run "$src/examples/koch_snowflake.g2d" --max-elements 0
expect_code 1 "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=6 --max-elements 1000 -o guard.svg --json guard.json --keep-partial
grep -q '"stopped": "element_limit"' guard.json || fail "--max-elements --keep-partial: $(head -c 300 guard.json)"
steps=$(sed -n 's/.*"steps": \([0-9]*\).*/\1/p' guard.json | head -1)
# The partial graph is the one of its step: 3 edges, and 3 more per step.
[ "$(grep -c '<line ' guard.svg)" = $((3 + 3 * steps)) ] || fail "partial SVG of step $steps: $(grep -c '<line ' guard.svg) lines"

# Integer overflow in attribute arithmetic is an error naming the rule and the step
cat > overflow.g2d <<'G2D'
node P { n: int = 1; }
axiom { p: P at (0, 0); }
limit 100;
rule Double { match { p: P; } produce { p { n = p.n * 2 }; } }
G2D
expect_code 1 "$g2d" run overflow.g2d --no-svg
grep -q '^overflow.g2d:4:49: error: integer overflow (in rule `Double`, step 63)$' err.txt || fail "integer overflow: $(cat err.txt)"

# NaN and infinite positions are errors naming the rule and the step, interpreted and compiled alike
printf 'node P;\naxiom { p: P at (0, 0); }\nlimit 3;\nrule N { match { p: P; } produce { p at (sqrt(-1), 0); } }\n' > nan.g2d
printf 'node P;\naxiom { p: P at (0, 0); }\nlimit 3;\nrule I { match { p: P; } produce { p at (pow(10, 400), 0); } }\n' > inf.g2d
expect_code 1 "$g2d" run nan.g2d -o nan.svg
grep -qx 'nan.g2d:4:42: error: the result is not a number (NaN) (in rule `N`, step 1)' err.txt || fail "NaN position: $(cat err.txt)"
[ -e nan.svg ] && fail "a NaN position left an output"
expect_code 1 "$g2d" run inf.g2d -o inf.svg
grep -qx 'inf.g2d:4:42: error: the result is infinite (in rule `I`, step 1)' err.txt || fail "infinite position: $(cat err.txt)"
cp err.txt inf.interpreted.txt
expect_code 0 "$g2d" build inf.g2d -o inf_program
expect_code 1 ./inf_program -o inf.svg
cmp -s err.txt inf.interpreted.txt || fail "compiled infinite-position error differs: $(cat err.txt)"

# A numeric fault names the production and the step; --keep-partial writes the step before it
cat > fault.g2d <<'G2D'
node P { n: int = 3; }
axiom { p: P at (0, 0); }
limit 10;
rule Count { match { p: P; } produce { p at (10 / p.n, 0) { n = p.n - 1 }; } }
G2D
expect_code 1 "$g2d" run fault.g2d -o fault.svg
grep -q 'division by zero.*(in rule `Count`, step 4)' err.txt || fail "numeric fault: $(cat err.txt)"
[ -e fault.svg ] && fail "a numeric fault left an output"
expect_code 1 "$g2d" run fault.g2d -o fault.svg --json fault.json --keep-partial
grep -q '"steps": 3' fault.json && grep -q '"stopped": "error"' fault.json || fail "fault --keep-partial: $(head -c 400 fault.json)"
grep -q '"n": 0' fault.json || fail "the partial graph is not step 3's: $(cat fault.json)"
expect_code 0 "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=6 --max-elements 30000 --no-svg

# An interrupted run leaves no temporary files and no output. The signal is
# sent once the output's temporary file exists (its handler is installed by
# then): a background job starts with SIGINT ignored, so a signal during a
# slow start (sanitizers, a loaded machine) would be lost and the run finish.
"$g2d" run spin.g2d --steps 100000000 -o interrupted.svg >/dev/null 2>&1 &
pid=$!
for _ in $(seq 600); do ls | grep -q 'interrupted.svg.tmp-' && break; sleep 0.1; done
kill -INT "$pid"; wait "$pid" 2>/dev/null
ls | grep -q 'interrupted.svg' && fail "an interrupted run left $(ls | grep interrupted)"

finish
