#!/usr/bin/env bash
# G^3's house, cupboard and sofa (Laganeckiene 2012, Figs 5.1-5.3, Table
# 5.1): examples/g3_house.g2d, g3_cupboard.g2d and g3_sofa.g2d, our own rule
# files of about the thesis's sizes, made with compound commands and merging.
# Each model, with its defaults and one other setting, derives with the
# engine's matches checked against a full search after every step, the
# compiled program gives the same bytes, and:
# - merging makes one consistent mesh of each: no two nodes at one place, no
#   two edges with the same ends, every face side an edge and every edge a
#   side, each side run once each way; V - E + F is 2 for the house and the
#   cupboard (one closed surface, as the thesis's) and 8 for the sofa (four
#   closed boxes);
# - house (612 nodes, 1146 edges, 536 faces): the `Windows` compound gives
#   each of the five wall faces (the back, the sides, the front on each side
#   of the door) `windows` windows per storey, centred in equal bays of that
#   face's own width (4.4, 10 and 7); the `Door` compound's leaf is in the
#   front's middle, as high as the ground floor's window heads;
# - cupboard (245 nodes, 476 edges, 233 faces): the one `Drawer` compound
#   gives every panel a front, a raised panel and a handle (boxes grown by
#   the nested `Extrude`, whose conditions count faces within its scope); on
#   a drawer the handle lies along the panel, in its middle, 0.4 of its
#   width long; on a door (higher than wide) it stands upright next to the
#   middle, 0.4 of its height long; with `drawers=5` the doors are wider
#   than high and get a drawer's handle; the four legs reach the ground;
# - sofa (6616 nodes, 10384 edges, 3776 faces): one maple leaf on every tile
#   of every side of every box (upright, level, facing x and y), in the
#   tile's plane, its 24 outline points at the radii of the maple shape
#   however it is turned; the leaves on upright tiles all point up with
#   `turned=false`, and only some with the default random turns.
# Usage: g3_furniture_test.sh G2D SOURCE_DIR [COMPILED]   (COMPILED=no: the interpreter only)
set -u
g2d="$1"; src="$2"; compiled="${3:-yes}"
source "$(dirname "$0")/test_lib.sh"
export PYTHONPATH="$src/tests/pylib"

# The mesh checks shared by the three models.
cat > mesh.py <<'PY'
import json, math
from collections import Counter, defaultdict
from mesh_checks import oriented_sides

def load(path, counts, steps):
    d = json.load(open(path))
    got = (len(d["nodes"]), len(d["links"]), len(d["faces"]))
    assert got == counts, got
    assert d["graph"]["steps"] == steps and d["graph"]["stopped"] == "terminal", d["graph"]
    return d, {v["id"]: tuple(v["pos"]) for v in d["nodes"]}

def consistent(d, pos, euler):
    V, E, F = len(d["nodes"]), len(d["links"]), len(d["faces"])
    assert V - E + F == euler, (V, E, F)
    places = Counter(tuple(round(c, 6) for c in p) for p in pos.values())
    assert max(places.values()) == 1, [p for p, n in places.items() if n > 1][:5]
    ends = Counter(frozenset((l["source"], l["target"])) for l in d["links"])
    assert all(len(k) == 2 for k in ends), "an edge from a node to itself"
    assert max(ends.values()) == 1, "two edges with the same ends"
    sides = oriented_sides(d["faces"])
    assert set(frozenset(s) for s in sides) == set(ends), "a side without an edge, or an edge on no face"
PY

# model NAME GRAMMAR ARGS...: runs the grammar (checking the matches); with
# COMPILED=yes the program bin_GRAMMAR must write the same bytes.
model() {
  local name="$1" grammar="$2"; shift 2
  expect_code 0 "$g2d" run "$src/examples/$grammar.g2d" "$@" --json "i_$name.json" -o "i_$name.svg" --verify-matches
  if [ "$compiled" = yes ]; then
    expect_code 0 "./bin_$grammar" "$@" --json "c_$name.json" -o "c_$name.svg"
    for ext in json svg; do cmp -s "i_$name.$ext" "c_$name.$ext" || fail "$name: interpreted and compiled $ext differ"; done
  fi
}
if [ "$compiled" = yes ]; then
  for g in g3_house g3_cupboard g3_sofa; do expect_code 0 "$g2d" build "$src/examples/$g.g2d" -o "bin_$g"; done
fi

# ---- the house ----
model house g3_house
model house_small g3_house -D windows=2 -D storeys=1
for run in "house 3 2 612 1146 536" "house_small 2 1 220 409 191"; do
  set -- $run
  python3 - "i_$1.json" "$2" "$3" "$4" "$5" "$6" <<'PY' || fail "$1: wrong house"
import sys; sys.path.insert(0, ".")
from mesh import *
windows, storeys = int(sys.argv[2]), int(sys.argv[3])
d, pos = load(sys.argv[1], tuple(int(x) for x in sys.argv[4:7]), 32)
consistent(d, pos, 2)
kinds = Counter(f["kind"] for f in d["faces"])
assert kinds["Glass"] == 4 * windows * storeys * 5, kinds       # four panes a window
assert (kinds["Leaf"], kinds["Roof"], kinds["Gable"]) == (1, 2, 2), kinds
# a window's centre is where its four panes meet; the glass is 0.18 in the wall
panes = Counter(c for f in d["faces"] if f["kind"] == "Glass" for c in f["corners"])
rows = defaultdict(list)
for x, y, z in (pos[n] for n, k in panes.items() if k == 4):
    wall = "front" if abs(y - 0.18) < 1e-9 else "back" if abs(y - 6.82) < 1e-9 else "left" if abs(x - 0.18) < 1e-9 else "right"
    assert wall != "right" or abs(x - 9.82) < 1e-9, (x, y, z)
    rows[(wall, round(z, 9))].append(x if wall in ("front", "back") else y)
def bays(a, b): return [a + (b - a) / windows * (i + 0.5) for i in range(windows)]
want = {"front": bays(0, 4.4) + bays(5.6, 10), "back": bays(0, 10), "left": bays(0, 7), "right": bays(0, 7)}
assert sorted(rows) == sorted((w, round(3 * s + 1.6, 9)) for w in want for s in range(storeys)), sorted(rows)
for (wall, z), got in rows.items():
    assert len(got) == len(want[wall]) and all(abs(a - b) < 1e-9 for a, b in zip(sorted(got), want[wall])), (wall, z, sorted(got))
door = [pos[c] for f in d["faces"] if f["kind"] == "Leaf" for c in f["corners"]]
assert sorted(set(round(p[0], 9) for p in door)) == [4.4, 5.6] and sorted(set(round(p[2], 9) for p in door)) == [0, 2.3], door
PY
done

# ---- the cupboard ----
model cupboard g3_cupboard
model cupboard_5 g3_cupboard -D drawers=5
for run in "cupboard 3 245 476 233" "cupboard_5 5 347 678 333"; do
  set -- $run
  python3 - "i_$1.json" "$2" "$3" "$4" "$5" <<'PY' || fail "$1: wrong cupboard"
import sys; sys.path.insert(0, ".")
from mesh import *
drawers = int(sys.argv[2])
d, pos = load(sys.argv[1], tuple(int(x) for x in sys.argv[3:6]), 56)
consistent(d, pos, 2)
faces = d["faces"]
def extent(f):
    ps = [pos[c] for c in f["corners"]]
    return [(min(p[i] for p in ps), max(p[i] for p in ps)) for i in range(3)]
panels = 2 * drawers + 2
# every panel: a front, a raised panel and a handle, each a box of four sides
assert Counter(f["tone"] for f in faces if f["kind"] == "Side") == {0: 8 * panels, 1: 4 * panels, 2: 16}
handles = [f for f in faces if f["kind"] == "Front" and f["tone"] == 1]
assert len(handles) == panels, len(handles)
legs = [extent(f) for f in faces if f["kind"] == "Front" and f["tone"] == 2]
assert len(legs) == 4 and all(e[2] == (0, 0) for e in legs), legs
top = 0.22 + 0.25 * drawers                 # the doors' bottom; they reach 1.92
for f in handles:
    (x0, x1), (y0, y1), (z0, z1) = extent(f)
    assert y0 == y1 < 0, (y0, y1)           # in front of the panel
    cx, cz = (x0 + x1) / 2, (z0 + z1) / 2
    if cz < top or 1.92 - top < 0.8:        # a drawer, or a door wider than high
        assert abs(x1 - x0 - 0.4 * 0.8) < 1e-9 and z1 - z0 < x1 - x0, extent(f)
        assert min(abs(cx - 0.4), abs(cx - 1.2)) < 1e-9, cx
    else:                                   # a door: upright, next to the middle
        assert abs(z1 - z0 - 0.4 * (1.92 - top)) < 1e-9 and x1 - x0 < z1 - z0, extent(f)
        assert abs(abs(cx - 0.8) - 0.2) < 1e-9, cx
PY
done

# ---- the sofa ----
model sofa g3_sofa
model sofa_upright g3_sofa -D turned=false
for run in "sofa true" "sofa_upright false"; do
  set -- $run
  python3 - "i_$1.json" "$2" <<'PY' || fail "$1: wrong sofa"
import sys; sys.path.insert(0, ".")
from mesh import *
turned = sys.argv[2] == "true"
d, pos = load(sys.argv[1], (6616, 10384, 3776), 30)
consistent(d, pos, 8)
faces = d["faces"]
kinds = Counter(f["kind"] for f in faces)
# a leaf's eight sectors end at its centre; around it, eight pieces of the tile
sectors = defaultdict(list)
for f in faces:
    if f["kind"] == "Leaf":
        sectors[f["corners"][-1]].append(f)
assert len(sectors) == 236 and all(len(s) == 8 for s in sectors.values()) and kinds == {"Leaf": 1888, "Cover": 1888}, kinds
def lobe(k): return [1.0, 0.68, 0.42, 0.62, 0.95, 0.72, 0.52, 0.6, 0.72, 0.42, 0.28, 0.16, 0.6][k]
shape = sorted(lobe(min(abs(j - 6), 24 - abs(j - 6))) for j in range(24))
facing, up = Counter(), 0
for c, fs in sectors.items():
    o = pos[c]
    outline = set(p for f in fs for p in f["corners"][:-1])
    flat = [i for i in range(3) if all(abs(pos[p][i] - o[i]) < 1e-9 for p in outline)]
    assert len(outline) == 24 and len(flat) == 1, (len(outline), flat)     # in the tile's plane
    r = {p: math.dist(pos[p], o) for p in outline}
    size = max(r.values())
    assert all(abs(a - b) < 1e-9 for a, b in zip(sorted(x / size for x in r.values()), shape))
    facing["xyz"[flat[0]]] += 1
    if flat[0] != 2:                        # on an upright tile: does the top lobe point up?
        up += abs(pos[max(r, key=r.get)][2] - o[2] - size) < 1e-9
assert set(facing) == {"x", "y", "z"}, facing
upright = facing["x"] + facing["y"]
assert (0 < up < upright) if turned else up == upright, (up, upright)
PY
done

finish
