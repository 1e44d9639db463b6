#!/usr/bin/env bash
# examples/g3_tree_box.g2d: G^3's tree in a box (Figs 3.6, 5.4). With
# intersection testing every branch stays inside the closed box of nine
# faces (a branch whose cylinder would reach a wall is not made), and the tree is
# still a tree (every node one stem in); without testing the same growth
# goes through the walls and is bigger; `-D rounds=3` runs 3 rounds of 4 commands.
# Interpreted and compiled runs give the same bytes.
# Usage: g3_tree_box_test.sh G2D SOURCE_DIR [COMPILED]   (COMPILED=no: the interpreter only)
set -u
g2d="$1"; src="$2"; compiled="${3:-yes}"
source "$(dirname "$0")/test_lib.sh"
grammar="$src/examples/g3_tree_box.g2d"

[ "$compiled" = yes ] && expect_code 0 "$g2d" build "$grammar" -o tree
for testing in true false; do
  expect_code 0 "$g2d" run "$grammar" -D "testing=$testing" --json "i_$testing.json" --no-svg
  [ "$compiled" = yes ] && compiled_same ./tree "$testing" json -D "testing=$testing"
done
python3 - i_true.json i_false.json <<'PY' || fail "wrong tree"
import json, sys
tested, untested = (json.load(open(f)) for f in sys.argv[1:])
def inside(p):
    return -1 < p[0] < 1 and -1 < p[1] < 1 and 0 < p[2] < 2
for d in (tested, untested):
    assert len(d["faces"]) == 9 and d["graph"]["steps"] == 52, (len(d["faces"]), d["graph"])
tree = [v for v in tested["nodes"] if v["kind"] == "N"]
assert len(tree) == 6890, len(tree)
assert all(inside(v["pos"]) for v in tree), [v["pos"] for v in tree if not inside(v["pos"])][:3]
# a branch is a cylinder kept clear of the walls by its radius (§16.8): every
# node is farther from every wall than its own radius, but the trunk's root,
# which the axiom stands 0.02 above the floor with radius 0.03
def clearance(v):
    p = v["pos"]
    return min(p[0] + 1, 1 - p[0], p[1] + 1, 1 - p[1], p[2], 2 - p[2]) - v["radius"]
close = [v["pos"] for v in tree if clearance(v) <= 0]
assert close == [[0, 0, 0.02]], close
wild = [v for v in untested["nodes"] if v["kind"] == "N"]
assert len(wild) > len(tree) and not all(inside(v["pos"]) for v in wild)
# every tree node but the root has one stem in; tips none out, forks at most two
ins = {}
for l in tested["links"]:
    ins[l["target"]] = ins.get(l["target"], 0) + 1
assert sum(1 for v in tree if ins.get(v["id"], 0) != 1) == 1
PY
# The rounds are `repeat rounds { Round; }`: four commands a round.
expect_code 0 "$g2d" run "$grammar" -D rounds=3 --stats --no-svg
grep -q '"steps": 12,' out.txt || fail "rounds=3: $(cat out.txt)"
finish
