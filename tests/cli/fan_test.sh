#!/usr/bin/env bash
# examples/fan.g2d: one rule with `for (u, v) in f.sides` fans a triangle, a
# quad and a hexagon around their centroids: 3 + 4 + 6 = 13 faces after one
# round, three times as many after each further round, every face a
# counter-clockwise triangle, their areas summing to the three polygons';
# the compiled program gives the same bytes, and incremental matching agrees
# with a full search after every step.
# Usage: fan_test.sh G2D SOURCE_DIR [MAX_ROUNDS]   (default 3; sanitized builds use less)
set -u
g2d="$1"; src="$2"; max_rounds="${3:-3}"
source "$(dirname "$0")/test_lib.sh"
grammar="$src/examples/fan.g2d"

expect_code 0 "$g2d" build "$grammar" -o fan
for r in $(seq 0 "$max_rounds"); do
  expect_code 0 "$g2d" run "$grammar" -D "rounds=$r" --json "i$r.json" -o "i$r.svg" --verify-matches
  expect_code 0 ./fan -D "rounds=$r" --json "c$r.json" -o "c$r.svg"
  cmp -s "i$r.json" "c$r.json" && cmp -s "i$r.svg" "c$r.svg" || fail "rounds $r: interpreted and compiled differ"
  python3 - "i$r.json" "$r" <<'PY' || fail "rounds $r: wrong fans"
import json, sys
d = json.load(open(sys.argv[1])); rounds = int(sys.argv[2])
faces = d["faces"]
want = 3 if rounds == 0 else 13 * 3 ** (rounds - 1)
assert len(faces) == want, (len(faces), want)
pos = {v["id"]: tuple(v["pos"]) for v in d["nodes"]}
def area(c):
    return sum(pos[c[i]][0] * pos[c[(i + 1) % len(c)]][1] - pos[c[(i + 1) % len(c)]][0] * pos[c[i]][1] for i in range(len(c))) / 2
if rounds > 0:
    assert all(len(f["corners"]) == 3 and area(f["corners"]) > 0 for f in faces), "not all counter-clockwise triangles"
    assert all(f["gen"] == rounds for f in faces)
total = sum(area(f["corners"]) for f in faces)
polygons = 1.732 + 4 + 3 * 0.866   # the triangle, the square and the hexagon of the axiom (shoelace)
assert abs(total - polygons) < 1e-9, (total, polygons)
PY
done
finish
