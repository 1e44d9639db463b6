#!/usr/bin/env bash
# G^3's Fig. 3.11: on two 3×3 squares of unit quads side by side (3 rows ×
# 6 columns, sharing their middle edge), exactly four faces have eight
# neighbouring faces in G^3's sense (sharing at least a corner: the fact
# `touching`): the middle row's columns 2 to 5. `neighbours` (sharing a side)
# gives at most 4. Interpreted and compiled runs agree, and incremental
# matching agrees with a full search after every step.
# Usage: g3_neighbours_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"

python3 - > grid.g2d <<'PY'
print("node P;\nface Q { marked: bool = false; sides: int = 0; }")
print("axiom {")
for y in range(4):
    for x in range(7):
        print(f"    n{x}_{y}: P at ({x}, {y});")
for y in range(3):
    for x in range(6):
        print(f"    Q(n{x}_{y}, n{x+1}_{y}, n{x+1}_{y+1}, n{x}_{y+1});")
print("}")
print("""rule Mark {
    match { f: Q where f.touching == 8 and not f.marked; }
    produce { f { marked = true, sides = f.neighbours }; }
}
sequence { Mark; }""")
PY
expect_code 0 "$g2d" run grid.g2d --json i.json -o i.svg --verify-matches
expect_code 0 "$g2d" build grid.g2d -o grid
expect_code 0 ./grid --json c.json -o c.svg
cmp -s i.json c.json && cmp -s i.svg c.svg || fail "interpreted and compiled differ"
python3 - i.json <<'PY' || fail "wrong faces with eight neighbours"
import json, sys
d = json.load(open(sys.argv[1]))
pos = {v["id"]: v["pos"] for v in d["nodes"]}
marked = sorted((min(pos[c][0] for c in f["corners"]), min(pos[c][1] for c in f["corners"])) for f in d["faces"] if f["marked"])
assert marked == [(1, 1), (2, 1), (3, 1), (4, 1)], marked
assert all(f["sides"] == 4 for f in d["faces"] if f["marked"])
PY
finish
