#!/usr/bin/env bash
# `repeat N { … }` and named command lists (`sequence NAME { … }`, G^3
# §2.4.6) in tests/cli/sequence_repeat.g2d: for several counts, the steps
# run in the order the lists say (each P node's age and direction: Grow
# right, Up; the compound's repeat sprouts Q nodes), both back ends give
# the same bytes with matches verified; a negative count given as a
# parameter stops the run with an error at the count (both back ends);
# `g2d check` warns of `repeat 0` and of a named list that nothing names.
# Usage: sequence_repeat_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"
grammar="$src/tests/cli/sequence_repeat.g2d"

expect_code 0 "$g2d" build "$grammar" -o seq
for counts in "3 2" "1 0" "0 3" "2 4"; do
  set -- $counts; n=$1; inner=$2; stem="${n}_$inner"
  expect_code 0 "$g2d" run "$grammar" -D "n=$n" -D "inner=$inner" --json "i_$stem.json" -o "i_$stem.svg" --verify-matches
  compiled_same ./seq "$stem" "json svg" -D "n=$n" -D "inner=$inner"
  python3 - "i_$stem.json" "$n" "$inner" <<'PY' || fail "n=$n inner=$inner: wrong order"
import json, sys
d = json.load(open(sys.argv[1])); n, inner = int(sys.argv[2]), int(sys.argv[3])
want = (["R", "U"] * inner + ["R"]) * n          # the steps of `repeat n { Block; }`
assert d["graph"]["steps"] == len(want) + inner and d["graph"]["stopped"] == "terminal", d["graph"]
p = sorted((v for v in d["nodes"] if v["kind"] == "P"), key=lambda v: v["age"])
assert [v["age"] for v in p] == list(range(len(want) + 1)), [v["age"] for v in p]
got = ["R" if b["pos"][0] > a["pos"][0] else "U" for a, b in zip(p, p[1:])]
assert got == want, (got, want)
q = sorted((v for v in d["nodes"] if v["kind"] == "Q"), key=lambda v: v["age"])
assert [v["age"] for v in q] == [0] + [len(want) + k for k in range(1, inner + 1)], [v["age"] for v in q]
PY
done

# A negative count is known only when the run starts: an error at the count.
expect_code 1 "$g2d" run "$grammar" -D n=-2 --no-svg
grep -q 'sequence_repeat.g2d:20:19: error: a repeat count cannot be negative (it is -2)' err.txt || fail "interpreted: $(cat err.txt)"
expect_code 1 ./seq -D n=-2 --no-svg
grep -q 'sequence_repeat.g2d:20:19: error: a repeat count cannot be negative (it is -2)' err.txt || fail "compiled: $(cat err.txt)"

# What can never run is a warning.
cat > zero.g2d <<'G2D'
node P;
axiom { a: P; }
rule Grow { match { a: P where a.degree == 0; } produce { a; b: P at a.pos + (1, 0); a -[E]- b; } }
edge E;
sequence Unused { Grow; }
sequence { repeat 0 { Grow; } Grow; }
G2D
expect_code 0 "$g2d" check zero.g2d
grep -q 'zero.g2d:5:10: warning: sequence `Unused` is named by no list: it never runs' err.txt || fail "no unused-list warning: $(cat err.txt)"
grep -q 'zero.g2d:6:19: warning: `repeat 0` never runs its entries' err.txt || fail "no repeat-0 warning: $(cat err.txt)"
finish
