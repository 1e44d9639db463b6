#!/usr/bin/env bash
# examples/g3_box.g2d: G^3's Table 3.1. Create face on a square's sides, then
# Split edge on the hypotenuses: 12 nodes, 16 edges, 5 faces without merging;
# with merging 8, 12 and 5: the corners of an open unit box, its 12 edges
# (no two with the same ends), five quads (no corner twice), every face a
# unit square. Interpreted and compiled runs give the same bytes (SVG, JSON,
# OBJ), and the OBJ carries the z.
# Usage: g3_box_test.sh G2D SOURCE_DIR [COMPILED]   (COMPILED=no: the
# interpreter only, as sanitized builds do: building the program there is slow)
set -u
g2d="$1"; src="$2"; compiled="${3:-yes}"
source "$(dirname "$0")/test_lib.sh"
grammar="$src/examples/g3_box.g2d"

[ "$compiled" = yes ] && expect_code 0 "$g2d" build "$grammar" -o box
for merge in false true; do
  expect_code 0 "$g2d" run "$grammar" -D "merge=$merge" --json "i_$merge.json" --obj "i_$merge.obj" -o "i_$merge.svg" --verify-matches
  if [ "$compiled" = yes ]; then
    compiled_same ./box "$merge" "json obj svg" -D "merge=$merge"
  fi
  python3 - "i_$merge.json" "i_$merge.obj" "$merge" <<'PY' || fail "merge=$merge: wrong box"
import json, sys
d = json.load(open(sys.argv[1])); merged = sys.argv[3] == "true"
counts = (len(d["nodes"]), len(d["links"]), len(d["faces"]))
assert counts == ((8, 12, 5) if merged else (12, 16, 5)), counts
assert d["graph"]["steps"] == 2 and d["graph"]["stopped"] == "terminal", d["graph"]
pos = {v["id"]: tuple(v["pos"]) for v in d["nodes"]}
assert all(len(p) == 3 for p in pos.values())
assert all(v["radius"] == 0.04 for v in d["nodes"]), [v["radius"] for v in d["nodes"]]
# each command is one step: the square is the axiom's, the sides Create face's
assert sorted(f["age"] for f in d["faces"]) == [0, 1, 1, 1, 1], [f["age"] for f in d["faces"]]
for f in d["faces"]:
    c = f["corners"]
    assert len(c) == 4 and len(set(c)) == 4, c
    # a unit square: four sides of length 1 (the corners in cyclic order)
    for i in range(4):
        a, b = pos[c[i]], pos[c[(i + 1) % 4]]
        assert abs(sum((x - y) ** 2 for x, y in zip(a, b)) - 1) < 1e-12, (c, a, b)
if merged:
    assert sorted(pos.values()) == sorted((x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)), sorted(pos.values())
    ends = [frozenset((l["source"], l["target"])) for l in d["links"]]
    assert len(set(ends)) == 12, "two edges with the same ends"
    # every side of every face is an edge: the box is closed along its seams
    for f in d["faces"]:
        c = f["corners"]
        assert all(frozenset((c[i], c[(i + 1) % 4])) in ends for i in range(4)), c
obj = open(sys.argv[2]).read().split("\n")
vs = [l for l in obj if l.startswith("v ")]
assert len(vs) == counts[0] and any(l.endswith(" 1") for l in vs), vs
PY
done
finish
