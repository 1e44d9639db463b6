#!/usr/bin/env bash
# The 3D exports (language.md §6): OBJ with normals and an MTL of the faces'
# colours, OBJ as triangles, binary glTF checked by the Khronos validator
# (tests/gltf-check); `g2d run` and a compiled program write the same bytes;
# a face without triangles and an unwritable folder are clear errors that
# leave no file.
# Usage: exports_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"
validate() { node "$src/tests/gltf-check/validate.js" "$@"; }

# glTF: valid for the validator (no error, no warning), 3D and 2D.
for ex in g3_sofa g3_house g3_tree_box g3_windmill floor_plan; do
  expect_code 0 "$g2d" run "$src/examples/$ex.g2d" --no-svg --gltf "i_$ex.glb" --obj "i_$ex.obj" --obj-triangles
  validate "i_$ex.glb" > "$ex.report" || fail "$ex: the validator: $(head -8 "$ex.report")"
  # The same run again: the same bytes.
  expect_code 0 "$g2d" run "$src/examples/$ex.g2d" --no-svg --gltf "again_$ex.glb"
  cmp -s "i_$ex.glb" "again_$ex.glb" || fail "$ex: two runs wrote different glTF"
done

# The glTF's meshes are named by kind; the tree's thick stems are tubes, the
# glass box's panes translucent; the house's walls stand up (glTF is y-up).
python3 - i_g3_tree_box.glb i_g3_house.glb i_floor_plan.glb <<'PY' || fail "glTF contents"
import json, struct, sys
def gltf(path):
    data = open(path, "rb").read()
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF" and version == 2 and length == len(data), (magic, version, length)
    size, kind = struct.unpack_from("<I4s", data, 12)
    assert kind == b"JSON"
    return json.loads(data[20:20 + size])
tree = gltf(sys.argv[1])
meshes = {m["name"]: m for m in tree["meshes"]}
assert [m["name"] for m in tree["meshes"]] == ["Stem", "Side", "Pane"], sorted(meshes)
glass = tree["materials"][meshes["Pane"]["primitives"][0]["material"]]
assert glass["alphaMode"] == "BLEND" and glass["pbrMetallicRoughness"]["baseColorFactor"][3] == 0.25, glass
# Stems have a radius: triangles (tubes); the box's sides none: lines.
assert [p.get("mode", 4) for p in meshes["Stem"]["primitives"]] == [4], meshes["Stem"]
assert [p.get("mode", 4) for p in meshes["Side"]["primitives"]] == [1], meshes["Side"]
house = gltf(sys.argv[2])
names = [m["name"] for m in house["meshes"]]
assert names[:2] == ["Wall", "Gable"], names
wall = house["accessors"][house["meshes"][0]["primitives"][0]["attributes"]["POSITION"]]
assert wall["max"][1] - wall["min"][1] > 1, wall   # height along glTF's y
plan = gltf(sys.argv[3])
assert [m["name"] for m in plan["meshes"]] == ["Wall", "Room", "Yard"], plan["meshes"]   # kinds in declaration order
for a in plan["accessors"]:
    if "max" in a: assert a["max"][1] == 0 and a["min"][1] == 0, a   # a 2D grammar lies on the ground
PY

# three.js's GLTFLoader opens them: the house's seven face kinds as nodes, in order.
node "$src/tests/gltf-check/three_load.mjs" i_g3_house.glb i_floor_plan.glb > three.txt || fail "three.js: $(cat three.txt)"
grep -q '^i_g3_house.glb: Wall,Gable,Roof,Reveal,Frame,Glass,Leaf; [0-9]* meshes, [1-9][0-9]* triangles, 0 line sets$' three.txt \
  || fail "three.js: $(cat three.txt)"
grep -q '^i_floor_plan.glb: Wall,Room,Yard; 3 meshes, 7 triangles, 1 line sets$' three.txt || fail "three.js: $(cat three.txt)"

# Compiled: the same glTF, OBJ and MTL bytes.
for ex in g3_house floor_plan; do
  expect_code 0 "$g2d" build "$src/examples/$ex.g2d" -o "prog_$ex"
  mkdir -p c   # the OBJ names its MTL: the same names, in another folder
  expect_code 0 "./prog_$ex" --no-svg --gltf "c/i_$ex.glb" --obj "c/i_$ex.obj" --obj-triangles
  for ext in glb obj mtl; do cmp -s "i_$ex.$ext" "c/i_$ex.$ext" || fail "$ex: interpreted and compiled $ext differ"; done
done

# OBJ: a normal per face, named by its corners; materials from the fills.
cat > lit.g2d <<'G2D'
space 3d;
node P;
face Wall { style { fill = "#8cc3df"; } }
face Glass { style { fill = "steelblue"; fill_opacity = 0.5; } }
face Hidden { style { fill = "none"; } }
axiom {
    a: P at (0, 0, 0); b: P at (2, 0, 0); c: P at (2, 0, 1); d: P at (1, 0, 1); e: P at (0, 0, 1);
    f: P at (0, 1, 0); g: P at (0, 1, 1);
    Wall(a, b, c, d, e);
    Glass(a, e, g, f);
    Hidden(b, f, g);
}
G2D
expect_code 0 "$g2d" run lit.g2d --no-svg --obj lit.obj
cat > want.obj <<'OBJ'
# g2d: 7 nodes, 0 edges, 3 faces
mtllib lit.mtl
v 0 0 0
v 2 0 0
v 2 0 1
v 1 0 1
v 0 0 1
v 0 1 0
v 0 1 1
g Wall
usemtl fill_8cc3df
vn 0 -1 0
f 1//1 2//1 3//1 4//1 5//1
g Glass
usemtl fill_4682b480
vn -1 0 0
f 1//2 5//2 7//2 6//2
g Hidden
usemtl fill_00000000
vn 0.4472135954999579 0.8944271909999159 0
f 2//3 6//3 7//3
OBJ
diff want.obj lit.obj > /dev/null || fail "OBJ: $(diff want.obj lit.obj | head -8)"
cat > want.mtl <<'MTL'
newmtl fill_8cc3df
Kd 0.5490196078431373 0.7647058823529411 0.8745098039215686
d 1
illum 1

newmtl fill_4682b480
Kd 0.27450980392156865 0.5098039215686274 0.7058823529411765
d 0.5
illum 1

newmtl fill_00000000
Kd 0 0 0
d 0
illum 1

MTL
diff want.mtl lit.mtl > /dev/null || fail "MTL: $(diff want.mtl lit.mtl | head -8)"
# Triangles: the pentagon (with a straight corner at d) as three, the quad as two.
expect_code 0 "$g2d" run lit.g2d --no-svg --obj tri.obj --obj-triangles
[ "$(grep -c '^f ' tri.obj)" = 6 ] || fail "--obj-triangles: $(grep '^f ' tri.obj)"
grep '^f ' tri.obj | grep -qv '^f [0-9]*//[0-9]* [0-9]*//[0-9]* [0-9]*//[0-9]*$' && fail "a face that is no triangle: $(cat tri.obj)"
[ "$(grep -c '^vn ' tri.obj)" = 3 ] || fail "--obj-triangles: one normal a face: $(grep '^vn' tri.obj)"

# Many seeds: each seed's OBJ names its own MTL; the glTF is a single run's.
expect_code 0 "$g2d" run "$src/examples/subdivide.g2d" --seeds 1..2 --no-svg --obj 'o{seed}.obj' --gltf 'g{seed}.glb'
grep -qx 'mtllib o2.mtl' o2.obj && [ -s o2.mtl ] || fail "--seeds: o2.obj's MTL: $(head -3 o2.obj)"
expect_code 0 "$g2d" run "$src/examples/subdivide.g2d" --seed 2 --no-svg --gltf alone2.glb
cmp -s g2.glb alone2.glb || fail "--seeds: seed 2's glTF differs from a run alone"

# Nothing to draw (nodes only): still a valid file.
printf 'node P;\naxiom { a: P at (0, 0); b: P at (1, 0); }\n' > dots.g2d
expect_code 0 "$g2d" run dots.g2d --no-svg --gltf dots.glb
validate dots.glb > dots.report || fail "a glTF without meshes: $(cat dots.report)"

# A face whose corners are collinear: no triangles, a clear error, no files.
cat > flat.g2d <<'G2D'
space 3d;
node P;
face Sliver;
axiom { a: P at (0, 0, 0); b: P at (1, 0, 0); c: P at (2, 0, 0); Sliver(a, b, c); }
G2D
expect_code 1 "$g2d" run flat.g2d -o flat.svg --gltf flat.glb
grep -q 'flat.g2d: error: face 0 (Sliver.*no output written' err.txt || fail "collinear face, glTF: $(cat err.txt)"
expect_code 1 "$g2d" run flat.g2d -o flat.svg --obj flat.obj --obj-triangles
grep -q 'flat.g2d: error: face 0 (Sliver' err.txt || fail "collinear face, OBJ triangles: $(cat err.txt)"
ls flat.* | grep -v '^flat.g2d$' && fail "files written after the error: $(ls)"
# Without triangles the OBJ still takes it (a polygon; no normal).
expect_code 0 "$g2d" run flat.g2d --no-svg --obj flat.obj
grep -qx 'f 1 2 3' flat.obj || fail "a flat face as a polygon: $(cat flat.obj)"

# Unwritable places: a clear error, nothing written.
expect_code 1 "$g2d" run lit.g2d --no-svg --gltf missing/x.glb
grep -q 'missing/x.glb' err.txt || fail "--gltf into a missing folder: $(cat err.txt)"
mkdir ro && chmod a-w ro
if [ "$(id -u)" != 0 ]; then
  expect_code 1 "$g2d" run lit.g2d --no-svg --obj ro/x.obj
  grep -q 'ro/x' err.txt || fail "--obj into a read-only folder: $(cat err.txt)"
fi
expect_code 1 "$g2d" run lit.g2d --no-svg --obj missing/x.obj --gltf y.glb
[ -e y.glb ] && fail "a glTF written beside an OBJ that could not be"
expect_code 2 "$g2d" run lit.g2d --no-svg --obj-triangles
grep -q -- '--obj-triangles applies to OBJ output only' err.txt || fail "--obj-triangles alone: $(cat err.txt)"
expect_code 2 "$g2d" run lit.g2d --no-svg --obj x.mtl
grep -q 'name the OBJ FILE.obj' err.txt || fail "--obj x.mtl: $(cat err.txt)"
finish
