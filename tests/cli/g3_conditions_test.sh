#!/usr/bin/env bash
# G^3's conditions that g2d reads as facts: an edge's `degree` (the other
# edges at its ends: G^3's neighbouring edges) and the bounds of an edge's or
# a face's nodes, `lo` and `hi` (G^3's position condition "checked for all
# vertices": `f.hi.z < 0.5` holds when every corner is below 0.5). The branch
# added first changes the degrees the tags then read; incremental matching
# agrees with a full search after every step; interpreted and compiled runs
# give the same bytes; in 2D the bounds are vec2.
# Usage: g3_conditions_test.sh G2D SOURCE_DIR [COMPILED]
set -u
g2d="$1"; src="$2"; compiled="${3:-yes}"
source "$(dirname "$0")/test_lib.sh"

cat > cond.g2d <<'G2D'
space 3d;
node P;
edge E { tag: int = 0; }
face F { tag: int = 0; }
axiom {
    a: P at (0, 0, 0); b: P at (1, 0, 0); c: P at (2, 0, 0); d: P at (3, 0, 0);
    a -[E]- b; b -[E]- c; c -[E]- d;
    p: P at (0, 1, 0); q: P at (1, 1, 0); r: P at (1, 2, 1); s: P at (0, 2, 0);
    F(p, q, r, s);
    t: P at (2, 1, 0); u: P at (3, 1, 0); v: P at (3, 2, 0);
    F(t, u, v);
}
rule Grow {
    match { a: P where a.degree == 2; }
    produce { a; n: P at a.pos + (0, -1, 0); a -[E]- n; }
}
rule TagEdges {
    match { a: P; b: P; e: a -[E]- b where e.tag == 0; }
    produce { e { tag = e.degree + 1 }; }
}
rule TagFaces {
    match { f: F where f.tag == 0; }
    produce { f { tag = (f.hi.z < 0.5 ? 1 : 0) + (f.lo.x > 1.5 ? 10 : 0) + 100 }; }
}
sequence { Grow; TagEdges; TagFaces; }
G2D
expect_code 0 "$g2d" run cond.g2d --json i_cond.json -o i_cond.svg --verify-matches
if [ "$compiled" = yes ]; then
  expect_code 0 "$g2d" build cond.g2d -o cond
  compiled_same ./cond cond "json svg"
fi
python3 - i_cond.json <<'PY' || fail "wrong degrees or bounds"
import json, sys
d = json.load(open(sys.argv[1]))
pos = {v["id"]: tuple(v["pos"][:2]) for v in d["nodes"]}
tags = sorted((min(pos[l["source"]], pos[l["target"]]), max(pos[l["source"]], pos[l["target"]]), l["tag"]) for l in d["links"])
# b and c got a branch: a-b meets 2 edges, b-c 4, c-d 2, each branch 2
assert tags == [((0, 0), (1, 0), 3), ((1, -1), (1, 0), 3), ((1, 0), (2, 0), 5), ((2, -1), (2, 0), 3), ((2, 0), (3, 0), 3)], tags
assert sorted(f["tag"] for f in d["faces"]) == [100, 111], d["faces"]
PY
cat > flat.g2d <<'G2D'
node P;
edge E;
face F { tag: int = 0; }
axiom { a: P at (0, 0); b: P at (2, 0); c: P at (2, 1); F(a, b, c); a -[E]- b; }
rule Tag {
    match { f: F where f.tag == 0 and f.hi.x == 2 and f.lo.y == 0; a: P; b: P; e: a -[E]- b where e.hi.y == 0 and e.degree == 0; }
    produce { f { tag = 1 }; a; b; e; }
}
G2D
expect_code 0 "$g2d" run flat.g2d --json flat.json --no-svg --verify-matches
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); assert [f["tag"] for f in d["faces"]] == [1], d' flat.json || fail "2D bounds"
finish
