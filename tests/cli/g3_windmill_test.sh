#!/usr/bin/env bash
# examples/g3_windmill.g2d: G^3's windmill compound (Figs 3.13, 3.14) on one
# big square, four small ones and a pentagon. Every wall gets a hub (Split
# face), pulled out (Edit node) by a quarter of the wall's size, an axle
# (Create edge) a fifth of it long, and a sail per corner (Create face): 62
# nodes, 106 edges, 50 faces. The sizes follow the wall ("bigger square
# result in bigger mill"): the big square's axle is twice a small one's,
# and `-D scale=2` doubles every one (Fig 3.13b) with the same topology.
# Interpreted and compiled runs give the same bytes.
# Usage: g3_windmill_test.sh G2D SOURCE_DIR [COMPILED]   (COMPILED=no: the interpreter only)
set -u
g2d="$1"; src="$2"; compiled="${3:-yes}"
source "$(dirname "$0")/test_lib.sh"
grammar="$src/examples/g3_windmill.g2d"

[ "$compiled" = yes ] && expect_code 0 "$g2d" build "$grammar" -o mill
for scale in 1 2; do
  expect_code 0 "$g2d" run "$grammar" -D "scale=$scale" --json "i_$scale.json" -o "i_$scale.svg" --verify-matches
  [ "$compiled" = yes ] && compiled_same ./mill "$scale" "json svg" -D "scale=$scale"
  python3 - "i_$scale.json" "$scale" <<'PY' || fail "scale=$scale: wrong mills"
import json, math, sys
d = json.load(open(sys.argv[1])); scale = float(sys.argv[2])
assert (len(d["nodes"]), len(d["links"]), len(d["faces"])) == (62, 106, 50)
assert d["graph"]["steps"] == 4, d["graph"]
pos = {v["id"]: v["pos"] for v in d["nodes"]}
out = {}
for v in d["nodes"]:
    out.setdefault(v["id"], [])
for l in d["links"]:
    out[l["source"]].append(l["target"])
# hubs: pulled up by size/4 over their wall (z = 0), with an axle straight up size/5 long
hubs = sorted((pos[v["id"]] for v in d["nodes"] if abs(pos[v["id"]][2] - 0) > 1e-9 and len(out[v["id"]]) > 2), key=lambda p: p[0])
pentagon = [(8, 0), (9, 0.7), (8.6, 1.9), (7.4, 1.9), (7, 0.7)]
area = abs(sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(pentagon, pentagon[1:] + pentagon[:1]))) / 2
sizes = [2 * scale] + [1 * scale] * 4 + [math.sqrt(area) * scale]
heights = sorted(round(p[2], 9) for p in hubs)
want = sorted(round(s / 4, 9) for s in sizes)
assert len(hubs) == 6 and heights == want, (heights, want)
axles = []
for l in d["links"]:
    a, b = pos[l["source"]], pos[l["target"]]
    if abs(a[0] - b[0]) < 1e-12 and abs(a[1] - b[1]) < 1e-12:
        axles.append(round(b[2] - a[2], 9))
assert sorted(axles) == sorted(round(s / 5, 9) for s in sizes), sorted(axles)
PY
done
finish
