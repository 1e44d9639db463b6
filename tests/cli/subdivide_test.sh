#!/usr/bin/env bash
# examples/subdivide.g2d: depth d gives exactly 4^d faces, (2^d+1)^2 nodes and
# 2·2^d·(2^d+1) edges, V - E + F = 1 (Euler, the outer face not counted),
# every face a counter-clockwise square of side 2^-d whose corners are nodes
# and whose sides are edges; the compiled program gives the same bytes, and
# incremental matching agrees with a full search after every step.
# Usage: subdivide_test.sh G2D SOURCE_DIR [MAX_DEPTH]   (default 5; sanitized builds use less)
set -u
g2d="$1"; src="$2"; max_depth="${3:-5}"
source "$(dirname "$0")/test_lib.sh"
grammar="$src/examples/subdivide.g2d"

expect_code 0 "$g2d" build "$grammar" -o subdivide
for d in $(seq 0 "$max_depth"); do
  args=(-D "depth=$d" --json "i$d.json" -o "i$d.svg")
  if [ "$d" -le 3 ]; then args+=(--verify-matches); fi
  expect_code 0 "$g2d" run "$grammar" "${args[@]}"
  expect_code 0 ./subdivide -D "depth=$d" --json "c$d.json" -o "c$d.svg"
  cmp -s "i$d.json" "c$d.json" && cmp -s "i$d.svg" "c$d.svg" || fail "depth $d: interpreted and compiled differ"
  python3 - "i$d.json" "$d" <<'PY' || fail "depth $d: wrong mesh"
import json, sys
d = json.load(open(sys.argv[1])); depth = int(sys.argv[2]); n = 2 ** depth
V, E, F = len(d["nodes"]), len(d["links"]), len(d["faces"])
assert (V, E, F) == ((n + 1) ** 2, 2 * n * (n + 1), 4 ** depth), (V, E, F)
assert V - E + F == 1, (V, E, F)
pos = {v["id"]: tuple(v["pos"]) for v in d["nodes"]}
sides = {frozenset((l["source"], l["target"])) for l in d["links"]}
for f in d["faces"]:
    c = f["corners"]
    assert len(c) == 4 and f["level"] == depth, f
    area = sum(pos[c[i]][0] * pos[c[(i + 1) % 4]][1] - pos[c[(i + 1) % 4]][0] * pos[c[i]][1] for i in range(4)) / 2
    assert abs(area - 1 / n ** 2) < 1e-12, ("not a counter-clockwise square of side 1/n", f, area)
    assert all(frozenset((c[i], c[(i + 1) % 4])) in sides for i in range(4)), ("a side is not an edge", f)
PY
done
finish
