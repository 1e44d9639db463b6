#!/usr/bin/env bash
# examples/g3_grid_split.g2d: G^3's Fig. 3.11 made with G^3's commands. Split
# edge twice and two-corner Split face cuts (§3.4) divide a square into 3×3
# unit cells; Split face on the cells with eight neighbouring faces then
# fans out the middle one (one square: 17 nodes, 28 edges, 12 faces) or the
# middle row's four inner cells (two squares sharing a side: 32, 61, 30).
# Every cut is a chord between two corners (no node made), every fan's node
# sits above its cell's centre, and the cells stay unit squares. Interpreted
# and compiled runs give the same bytes; incremental matching agrees with a
# full search after every step.
# Usage: g3_grid_split_test.sh G2D SOURCE_DIR [COMPILED]   (COMPILED=no: the
# interpreter only, as sanitized builds do)
set -u
g2d="$1"; src="$2"; compiled="${3:-yes}"
source "$(dirname "$0")/test_lib.sh"
grammar="$src/examples/g3_grid_split.g2d"

[ "$compiled" = yes ] && expect_code 0 "$g2d" build "$grammar" -o grid
for squares in 1 2; do
  expect_code 0 "$g2d" run "$grammar" -D "squares=$squares" --json "i_$squares.json" --obj "i_$squares.obj" -o "i_$squares.svg" --verify-matches
  [ "$compiled" = yes ] && compiled_same ./grid "$squares" "json obj svg" -D "squares=$squares"
  python3 - "i_$squares.json" "$squares" <<'PY' || fail "squares=$squares: wrong cells"
import json, sys
d = json.load(open(sys.argv[1])); squares = int(sys.argv[2])
counts = (len(d["nodes"]), len(d["links"]), len(d["faces"]))
assert counts == ((17, 28, 12) if squares == 1 else (32, 61, 30)), counts
assert d["graph"]["steps"] == 10 and d["graph"]["stopped"] == "terminal", d["graph"]
pos = {v["id"]: tuple(v["pos"]) for v in d["nodes"]}
raised = sorted(p for p in pos.values() if p[2] != 0)
# the fans' nodes: above the centres of the cells with eight neighbours
want = [(1.5, 1.5, 0.5)] if squares == 1 else [(x + 0.5, 1.5, 0.5) for x in (1, 2, 3, 4)]
assert raised == want, raised
flat = sorted(p for p in pos.values() if p[2] == 0)
assert flat == sorted((float(x), float(y), 0.0) for x in range(3 * squares + 1) for y in range(4)), flat
quads = [f["corners"] for f in d["faces"] if len(f["corners"]) == 4]
tris = [f["corners"] for f in d["faces"] if len(f["corners"]) == 3]
assert len(quads) == 9 * squares - len(want) and len(tris) == 4 * len(want), (len(quads), len(tris))
for c in quads:   # a unit square, its corners in order round it
    for i in range(4):
        a, b = pos[c[i]], pos[c[(i + 1) % 4]]
        assert abs(sum((x - y) ** 2 for x, y in zip(a, b)) - 1) < 1e-12, (c, a, b)
ends = {frozenset((l["source"], l["target"])) for l in d["links"]}
for f in d["faces"]:   # every side of every face is an edge
    c = f["corners"]
    assert all(frozenset((c[i], c[(i + 1) % len(c)])) in ends for i in range(len(c))), c
PY
done
finish
