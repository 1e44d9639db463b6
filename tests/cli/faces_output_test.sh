#!/usr/bin/env bash
# Faces in the outputs: SVG polygons below edges and nodes, the JSON "faces"
# list, and --obj, the same from `g2d run` and a compiled program; grammars
# without face kinds keep their JSON as it was.
# Usage: faces_output_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"
plan="$src/examples/floor_plan.g2d"

expect_code 0 "$g2d" run "$plan" -o i.svg --json i.json --obj i.obj
expect_code 0 "$g2d" build "$plan" -o plan
mkdir c   # the OBJ names its MTL: the same name, in another folder
expect_code 0 ./plan -o c.svg --json c.json --obj c/i.obj
for ext in svg json; do
  cmp -s "i.$ext" "c.$ext" || fail "interpreted and compiled $ext differ"
done
for ext in obj mtl; do
  cmp -s "i.$ext" "c/i.$ext" || fail "interpreted and compiled $ext differ"
done

cat > want.obj <<'OBJ'
# g2d: 11 nodes, 7 edges, 3 faces
mtllib i.mtl
v 0 0 0
v 6 0 0
v 10 0 0
v 10 5 0
v 6 5 0
v 0 5 0
v 0 8 0
v 10 8 0
v 8 5 0
v 0 2.5 0
v 6 2.5 0
g Room
usemtl fill_f2e6cc
vn 0 0 1
f 1//1 2//1 5//1 6//1
usemtl fill_dde8f0
vn 0 0 1
f 2//2 3//2 4//2 5//2
g Yard
usemtl fill_cfe8c4
vn 0 0 1
f 6//3 5//3 4//3 8//3 7//3
g edges
l 1 2
l 2 3
l 3 4
l 5 6
l 5 4
l 6 1
l 2 5
OBJ
diff want.obj i.obj > /dev/null || fail "OBJ: $(diff want.obj i.obj | head -5)"
# Each room's material: its fill (an attribute-driven style), one per colour.
grep -q '^Kd 0.9490196078431372 0.9019607843137255 0.8$' i.mtl || fail "MTL: $(cat i.mtl)"
[ "$(grep -c '^newmtl ' i.mtl)" = 3 ] || fail "MTL: one material per fill: $(cat i.mtl)"

python3 - i.json <<'PY' || fail "JSON faces"
import json, sys
d = json.load(open(sys.argv[1]))
faces = d["faces"]
assert [f["kind"] for f in faces] == ["Room", "Room", "Yard"], faces
assert faces[0] == {"id": 0, "kind": "Room", "corners": [0, 1, 4, 5], "age": 0, "name": "living", "floor": "#f2e6cc"}, faces[0]
assert faces[2]["corners"] == [5, 4, 3, 7, 6], faces[2]
ids = {n["id"] for n in d["nodes"]}
assert all(c in ids for f in faces for c in f["corners"]), "a corner is not a node"
PY

# NetworkX (Debian's python3-networkx) still reads the file; it ignores "faces".
/usr/bin/python3 - i.json <<'PY' || fail "networkx.node_link_graph cannot read the JSON with faces"
import json, sys
import networkx as nx
g = nx.node_link_graph(json.load(open(sys.argv[1])))
assert g.number_of_nodes() == 11 and g.number_of_edges() == 7
PY

# Faces are drawn first (below edges and nodes), filled by their kind's style.
first_polygon=$(grep -n '<polygon' i.svg | head -1 | cut -d: -f1)
first_line=$(grep -n '<line' i.svg | head -1 | cut -d: -f1)
[ "$(grep -c '<polygon' i.svg)" = 3 ] || fail "want 3 polygons: $(grep -c '<polygon' i.svg)"
[ "$first_polygon" -lt "$first_line" ] || fail "faces are not below the walls"
grep -q '<polygon points="0,0 6,0 6,5 0,5" fill="#f2e6cc" stroke="none"/>' i.svg || fail "the living room: $(grep polygon i.svg | head -1)"
grep -q 'opacity="0.85"' i.svg || fail "the garden's own style"

# Faces created by rules: the Koch snowflake of faces has 4^levels faces, all
# counter-clockwise (positive signed area), the same from the compiled program.
koch_faces="$src/examples/koch_faces.g2d"
expect_code 0 "$g2d" build "$koch_faces" -o kf
for levels in 1 2 3 4; do
  expect_code 0 "$g2d" run "$koch_faces" -D levels=$levels --no-svg --json kf$levels.json --verify-matches
  expect_code 0 ./kf -D levels=$levels --no-svg --json kfc$levels.json
  cmp -s kf$levels.json kfc$levels.json || fail "koch_faces levels=$levels: compiled JSON differs"
  python3 - kf$levels.json $levels <<'PY' || fail "koch_faces levels=$levels"
import json, sys
d = json.load(open(sys.argv[1])); levels = int(sys.argv[2])
pos = {n["id"]: n["pos"] for n in d["nodes"]}
faces = d["faces"]
assert len(faces) == 4 ** levels, len(faces)
def area(c):
    return sum(pos[c[i]][0] * pos[c[(i + 1) % len(c)]][1] - pos[c[(i + 1) % len(c)]][0] * pos[c[i]][1] for i in range(len(c))) / 2
assert all(area(f["corners"]) > 0 for f in faces), "a face runs clockwise"
assert sorted({f["depth"] for f in faces if f["kind"] == "Bump"}) == list(range(1, levels + 1))
PY
done

# The trace reads each kind's look from its own elements (a face is not a node).
expect_code 0 "$g2d" run "$koch_faces" -D levels=2 --no-svg --trace-json trace.json
python3 - trace.json <<'PY' || fail "trace kinds"
import json, sys
kinds = {k["name"]: k for k in json.load(open(sys.argv[1]))["kinds"]}
assert kinds["P"]["style"]["tag"] == "none", kinds["P"]
assert kinds["Bump"]["style"]["tag"] == "polygon", kinds["Bump"]
PY

# A grammar without face kinds writes no "faces" key.
expect_code 0 "$g2d" run "$src/examples/koch_snowflake.g2d" --no-svg --json k.json
grep -q '"faces"' k.json && fail "faces in a grammar without face kinds"
finish
