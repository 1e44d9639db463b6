#!/usr/bin/env bash
# G^3's compound commands with scopes (§3.3).
# 1. examples/g3_compound.g2d, Fig. 3.12: the cut-into-nine-then-split
#    compound on two squares side by side splits only the middle row's
#    columns 2 and 5 (in a square's scope the inner cells of columns 3 and 4
#    touch five faces, not eight); the shared side is split twice in all,
#    once per command, not once per scope. On one square it gives exactly what
#    the same commands give without a compound (examples/g3_grid_split.g2d).
# 2. Nesting (§3.3.5): a compound on every side within a compound on every
#    triangle. The shared side is one inner instance with two outer ones;
#    what the inner compound creates joins the outer scopes (the outer `Tag`
#    finds the new edges, each once), and the outer `Fan`'s corner condition
#    counts degrees within its triangle (2 everywhere; 3 at the shared
#    side's ends globally), so both hexagons fan out whole.
# 3. Table 3.2: a compound's `let` on its initial edge (l_ini = 3) as the
#    compound's length (l_cc = 5, or l_ini · l_cc when relative), read by a
#    contained Create edge (l_i = 2) as `C.l`, or the preceding edge's length
#    (l_pre = 0.5) when relative: 10, 1, 30, 1.
# Interpreted and compiled runs give the same bytes; incremental matching
# agrees with a full search after every step.
# Usage: g3_compound_test.sh G2D SOURCE_DIR [COMPILED]   (COMPILED=no: the interpreter only)
set -u
g2d="$1"; src="$2"; compiled="${3:-yes}"
source "$(dirname "$0")/test_lib.sh"
grammar="$src/examples/g3_compound.g2d"

same_bytes() {   # same_bytes GRAMMAR NAME ARGS...: compiled output equals the interpreter's i_NAME.*
  local g="$1" name="$2"; shift 2
  [ "$compiled" = yes ] || return 0
  expect_code 0 "$g2d" build "$g" -o "bin_$name"
  compiled_same "./bin_$name" "$name" "json svg" "$@"
}

expect_code 0 "$g2d" run "$grammar" --json i_two.json -o i_two.svg --verify-matches
same_bytes "$grammar" two
python3 - i_two.json <<'PY' || fail "Fig 3.12: wrong split"
import json, sys
d = json.load(open(sys.argv[1]))
counts = (len(d["nodes"]), len(d["links"]), len(d["faces"]))
assert counts == (30, 53, 24), counts
assert d["graph"]["steps"] == 10, d["graph"]
pos = [tuple(v["pos"]) for v in d["nodes"]]
assert sorted(p for p in pos if p[2] != 0) == [(1.5, 1.5, 0.5), (4.5, 1.5, 0.5)], pos
assert sorted(p[1] for p in pos if p[0] == 3) == [0, 1, 2, 3], "the shared side is split twice in all"
PY

expect_code 0 "$g2d" run "$grammar" -D squares=1 --json i_one.json -o i_one.svg --verify-matches
expect_code 0 "$g2d" run "$src/examples/g3_grid_split.g2d" -D squares=1 --json global_one.json --no-svg
python3 - i_one.json global_one.json <<'PY' || fail "one square: the compound and the plain commands differ"
import json, sys
# The same model: nodes, edges and faces by their positions (ids follow the order matches are found in).
def shape(d):
    pos = {v["id"]: tuple(v["pos"]) for v in d["nodes"]}
    def cycle(c):
        ps = [pos[i] for i in c]
        k = ps.index(min(ps))
        return tuple(ps[k:] + ps[:k])
    return (sorted(pos.values()), sorted(tuple(sorted((pos[l["source"]], pos[l["target"]]))) for l in d["links"]),
            sorted(cycle(f["corners"]) for f in d["faces"]), d["graph"]["steps"])
a, b = (json.load(open(f)) for f in sys.argv[1:])
assert shape(a) == shape(b)
PY

cat > nested.g2d <<'G2D'
space 3d;
node P;
edge E { tagged: bool = false; }
face F;
axiom {
    a: P at (0, 0, 0); b: P at (2, 0, 0); c: P at (0, 2, 0); d: P at (2, 2, 0);
    a -[E]- b; b -[E]- c; c -[E]- a; b -[E]- d; d -[E]- c;
    F(a, b, c); F(b, d, c);
}
rule SplitMid {
    match { a: P; b: P; s: a -[E]- b where s.length > 1.2; }
    produce { m: P at (a.pos + b.pos) / 2; a -[E]- m; s: m -[E]- b; insert m between a and b; }
}
rule Tag {
    match { a: P; b: P; e: a -[E]- b where e.age > 0 and not e.tagged; }
    produce { e { tagged = true }; }
}
rule Fan {
    match { f: F where f.corners == 6; }
    produce { split f around P at f.centroid with E for c in f.corners where c.degree == 2; }
}
compound Sides { match { a: P; b: P; s: a -[E]- b; } sequence { SplitMid; } }
compound Triangle { match { f: F; } sequence { Sides; Tag; Fan; } }
sequence { Triangle; }
G2D
expect_code 0 "$g2d" run nested.g2d --json i_nested.json -o i_nested.svg --verify-matches
same_bytes nested.g2d nested
python3 - i_nested.json <<'PY' || fail "nested compounds: wrong result"
import json, sys
d = json.load(open(sys.argv[1]))
counts = (len(d["nodes"]), len(d["links"]), len(d["faces"]))
assert counts == (11, 22, 12), counts            # 5 sides split once each; two fans of six
assert d["graph"]["steps"] == 3, d["graph"]      # SplitMid, Tag, Fan
assert sum(l["tagged"] for l in d["links"]) == 5, [l for l in d["links"] if l["tagged"]]
assert all(len(f["corners"]) == 3 for f in d["faces"]), d["faces"]
PY
cat > table32.g2d <<'G2D'
space 3d;
param cc_relative: bool = false;
param i_relative: bool = false;
node P;
edge E directed;
axiom { a: P at (0, 0, 0); b: P at (3, 0, 0); a -[E]-> b; }
compound C {
    match { a: P; b: P; e: a -[E]-> b where e.length > 2.5; }
    let l = cc_relative ? e.length * 5 : 5.0;
    sequence { Stub; CreateEdge; }
}
rule Stub {
    match { a: P; b: P; e: a -[E]-> b where e.length > 2.5; }
    produce { e; s: P at b.pos + (0, 0, 0.5); b -[E]-> s; }
}
rule CreateEdge {
    match { b: P; s: P; p: b -[E]-> s where p.length < 1; }
    produce { p; n: P at s.pos + p.direction * (i_relative ? p.length * 2 : C.l * 2); s -[E]-> n; }
}
sequence { C; }
G2D
for modes in "false false 10" "false true 1" "true false 30" "true true 1"; do
  set -- $modes
  expect_code 0 "$g2d" run table32.g2d -D cc_relative=$1 -D i_relative=$2 --json "i_t32_$1_$2.json" -o "i_t32_$1_$2.svg"
  python3 - "i_t32_$1_$2.json" "$3" <<'PY' || fail "Table 3.2: C_cc relative=$1, C_i relative=$2 should give $3"
import json, math, sys
d = json.load(open(sys.argv[1]))
pos = {v["id"]: v["pos"] for v in d["nodes"]}
last = max(d["links"], key=lambda l: l["id"])
assert abs(math.dist(pos[last["source"]], pos[last["target"]]) - float(sys.argv[2])) < 1e-12, last
PY
done
same_bytes table32.g2d t32_true_false -D cc_relative=true -D i_relative=false
finish
