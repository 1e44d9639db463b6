#!/usr/bin/env bash
# examples/extrude.g2d: one rule extrudes a triangle, a square and a hexagon
# into closed prisms through faces over all turns of a loop (`Top(all t)`,
# `Base(all u reversed)`). With one storey the tops and bases have exactly
# the corners the loop made, in turn order (the base reversed), at the
# footprints' corners raised by `height`; with any number of storeys the
# solids stay closed and consistently oriented (every side run once each
# way, every face's normal pointing out). Interpreted and compiled runs give
# the same bytes, and incremental matching agrees with a full search.
# Usage: extrude_test.sh G2D SOURCE_DIR [COMPILED]   (COMPILED=no: the interpreter only)
set -u
g2d="$1"; src="$2"; compiled="${3:-yes}"
source "$(dirname "$0")/test_lib.sh"
export PYTHONPATH="$src/tests/pylib"
grammar="$src/examples/extrude.g2d"

[ "$compiled" = yes ] && expect_code 0 "$g2d" build "$grammar" -o extrude
for storeys in 1 3; do
  expect_code 0 "$g2d" run "$grammar" -D "storeys=$storeys" --json "i_$storeys.json" -o "i_$storeys.svg" --verify-matches
  [ "$compiled" = yes ] && compiled_same ./extrude "$storeys" "json svg" -D "storeys=$storeys"
  python3 - "i_$storeys.json" "$storeys" <<'PY' || fail "storeys $storeys: wrong prisms"
import json, sys
from collections import Counter
from mesh_checks import oriented_sides
d = json.load(open(sys.argv[1])); storeys = int(sys.argv[2])
pos = {v["id"]: tuple(v["pos"]) for v in d["nodes"]}
faces = d["faces"]
kinds = Counter(f["kind"] for f in faces)
assert kinds == Counter({"Wall": 13 * storeys, "Top": 3, "Base": 3}), kinds
assert len(d["nodes"]) == 13 * (storeys + 1), len(d["nodes"])
# the footprints of the axiom: ids 0-2, 3-6, 7-12, counter-clockwise from above
footprints = [[0, 1, 2], [3, 4, 5, 6], [7, 8, 9, 10, 11, 12]]
bases = sorted(f["corners"] for f in faces if f["kind"] == "Base")
assert bases == sorted([list(reversed(c)) for c in footprints]), bases   # the turns' u, last turn first
if storeys == 1:
    for fp in footprints:
        top = next(f["corners"] for f in faces if f["kind"] == "Top" and pos[f["corners"][0]][:2] == pos[fp[0]][:2])
        assert [pos[t] for t in top] == [(pos[c][0], pos[c][1], pos[c][2] + 1.0) for c in fp], (top, fp)
oriented_sides(faces)   # closed and consistently oriented: every side once each way
assert len(d["nodes"]) - len(d["links"]) + len(faces) == 2 * 3   # three closed surfaces
# outward: each face's (Newell) normal points away from its solid's centre (the solids are convex)
def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def newell(c):
    n = [0.0, 0.0, 0.0]
    for i in range(len(c)):
        p, q = pos[c[i]], pos[c[(i + 1) % len(c)]]
        n[0] += (p[1] - q[1]) * (p[2] + q[2]); n[1] += (p[2] - q[2]) * (p[0] + q[0]); n[2] += (p[0] - q[0]) * (p[1] + q[1])
    return n
for fp in footprints:
    x0, x1 = min(pos[c][0] for c in fp), max(pos[c][0] for c in fp)
    mine = [f for f in faces if all(x0 - 1e-9 <= pos[c][0] <= x1 + 1e-9 for c in f["corners"])]
    ids = {c for f in mine for c in f["corners"]}
    centre = tuple(sum(pos[i][k] for i in ids) / len(ids) for k in range(3))
    for f in mine:
        c = f["corners"]
        mid = tuple(sum(pos[i][k] for i in c) / len(c) for k in range(3))
        assert sum(a * b for a, b in zip(newell(c), sub(mid, centre))) > 0, ("inward", f)
PY
done
finish
