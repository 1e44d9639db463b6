#!/usr/bin/env bash
# `g2d infer EXAMPLE`: the grammar inferred from an example shape (Merrell
# 2023) as the paper writes it, --stats as JSON, -o as g2d source that runs
# alike interpreted and compiled, and bad examples refused with the place of
# the fault.
# Usage: infer_command_test.sh G2D SOURCE_DIR
set -u
g2d="$1"; src="$2"
source "$(dirname "$0")/test_lib.sh"
examples="$src/examples/infer/merrell"
has() { grep -qF -- "$2" "$1" || fail "$1 lacks: $2"; }

expect_code 0 "$g2d" infer "$examples/2D Basic Shapes/triangle.json"
has out.txt 'example: Triangle (3 vertices, 3 edges)'
has out.txt 'primitives: 3'
has out.txt 'rules: 0, starter rules: 1'
has out.txt '  0: ^ (3 vertices) <-> nothing'

# The L: a step of the wall <-> a straight edge, in two directions; a rectangle starts it.
expect_code 0 "$g2d" infer "$examples/2D Basic Shapes/L.json"
has out.txt 'edge labels: 4 (3 edges snapped onto a shared direction)'
has out.txt 'rules: 2, starter rules: 1'
has out.txt '<-> edge 2 ^ 2'"'"
has out.txt '  2: ^ (4 vertices) <-> nothing'

expect_code 0 "$g2d" infer --stats "$examples/2D Branches/T.json"
python3 - out.txt <<'PY' || fail "T --stats"
import json, sys
s = json.load(open(sys.argv[1]))
want = {"vertices": 4, "edges": 3, "labels": 2, "primitives": 4, "left_over": 0, "starters": 1}
assert all(s[k] == v for k, v in want.items()), s
assert s["milliseconds"] >= 0
PY

# An SVG drawing: stroke colours are edge labels, fill colours areas.
expect_code 0 "$g2d" infer "$src/examples/infer/house.svg"
has out.txt 'example: House (9 vertices, 11 edges)'
has out.txt 'primitives: 8'
printf '<svg xmlns="http://www.w3.org/2000/svg">\n<circle r="3"/>\n</svg>\n' > round.svg
expect_code 1 "$g2d" infer round.svg
grep -q 'round.svg:2:' err.txt || fail "round.svg: no line in: $(cat err.txt)"

# A hierarchy cut short says so.
expect_code 0 "$g2d" infer --max-graphs 50 "$examples/2D Regions/hexagons.json"
has out.txt 'warning: the grammar may be incomplete:'

printf '[1, 1, "0,0,80,0,40,-40,40,40", "", "0,1,-1,-1,2,3,-1,-1", 1, 0, 0, 0, false]' > crossing.json
expect_code 1 "$g2d" infer crossing.json
has err.txt 'g2d infer: error: crossing.json: data[4], edge 0: the edge crosses data[4], edge 1; an example must be a plane drawing'
expect_code 1 "$g2d" infer missing.json
has err.txt 'g2d infer: error: cannot read missing.json'
printf '{"data": [1, 1, "0,0", ' > cut.json
expect_code 1 "$g2d" infer cut.json
has err.txt 'g2d infer: error: cut.json:1:24: not valid JSON: syntax error'
# Numbers beyond double's range, and values out of range, are located errors.
printf '[1, 1, "0,0,80,0",\n "", "0,1,-1,-1", 1, 0, 11e3081, 0, false]' > huge.json
expect_code 1 "$g2d" infer huge.json
has err.txt 'g2d infer: error: huge.json:2:25: not valid JSON: the number 11e3081 is out of range'
printf '[1, 1, "0,0,80,0", "", "0,7,-1,-1", 1, 0, 0, 0, false]' > pastend.json
expect_code 1 "$g2d" infer pastend.json
has err.txt 'g2d infer: error: pastend.json: data[4]: edge 0 names a vertex that does not exist'
printf '[1, 1, "0,0,80,0", "", "0,1e300,-1,-1", 1, 0, 0, 0, false]' > hugeindex.json
expect_code 1 "$g2d" infer hugeindex.json
has err.txt 'g2d infer: error: hugeindex.json: data[4]: edge 0 names a vertex that does not exist'
printf '[1, -3, "0,0,80,0", "", "0,1,-1,-1", 1, 0, 0, 0, false]' > negative.json
expect_code 1 "$g2d" infer negative.json
has err.txt 'g2d infer: error: negative.json: data[1]: the shape count -3 is out of range'
printf '{"data": [1, 1, "0,0,80,0", "", "0,1,-1,-1", 1, 0, 0, 0, false], "settings": "{\\"Extents\\": [1e999]}"}' > settings.json
expect_code 1 "$g2d" infer settings.json
has err.txt 'g2d infer: error: settings.json: "settings":1:14: not valid JSON: the number 1e999 is out of range'
expect_code 2 "$g2d" infer --angle-tolerance 90 "$examples/2D Branches/T.json"

# -o: the grammar as g2d source, clean for `g2d check --werror`; interpreted
# and compiled runs of it are byte-identical, with faces and labels.
expect_code 0 "$g2d" infer "$examples/2D Branches/T.json" -o t.g2d --iterations 200
has t.g2d 'layout angles {'
has t.g2d 'param iterations: int = 200;'
has t.g2d 'rule Start'
expect_code 0 "$g2d" check --werror t.g2d
expect_code 0 "$g2d" infer "$examples/2D Basic Shapes/square filled.json" -o sq.g2d --iterations 200
expect_code 0 "$g2d" run sq.g2d --seed 4 --json sq_run.json --no-svg
expect_code 0 "$g2d" build sq.g2d -o sq_bin
expect_code 0 ./sq_bin --seed 4 --json sq_built.json --no-svg
cmp -s sq_run.json sq_built.json || fail "square filled: interpreted and compiled JSON differ"
python3 - sq_run.json <<'PY' || fail "square filled: no faces or labels"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["nodes"] and d["faces"], "an empty output"
assert all(isinstance(l["label"], int) for l in d["links"])
assert all(isinstance(f["label"], int) for f in d["faces"])
PY
# Size and space: --size sets the target the cost steers toward, the canvas follows it.
expect_code 0 "$g2d" infer "$examples/2D Branches/T.json" --size 60 -o t60.g2d
has t60.g2d 'param target_vertices: int = 60;   // the example has 4'
has t60.g2d 'param iterations: int = 1000;'
has t60.g2d 'cost = 0.5 * abs(nodes - target_vertices);'
has t60.g2d 'canvas (0, 0) to (width, height);'
expect_code 0 "$g2d" run t60.g2d --stats --no-svg
python3 - out.txt <<'PY' || fail "T --size 60: not near the target"
import json, sys
s = json.load(open(sys.argv[1]))
assert 45 <= s["nodes"] <= 75, s
assert s["rejected_by_cost"] > 0, s
PY
expect_code 0 "$g2d" run t60.g2d --stats --no-svg -D target_vertices=20
python3 - out.txt <<'PY' || fail "T -D target_vertices=20: not near the target"
import json, sys
s = json.load(open(sys.argv[1]))
assert 12 <= s["nodes"] <= 28, s
PY
expect_code 1 "$g2d" infer "$examples/2D Branches/T.json" --size 0 -o zero.g2d
has err.txt 'g2d infer: error: --size 0: the target number of vertices must be at least 1'
[ -e zero.g2d ] && fail "--size 0 wrote a grammar"
# A canvas no edge fits in: an error, nothing written.
expect_code 1 "$g2d" run t60.g2d -D canvas_width=0.1 -D canvas_height=0.1 -o tiny.svg
has err.txt 'is smaller than the shortest edge of every edge kind'
[ -e tiny.svg ] && fail "a canvas too small wrote an SVG"

# --length-unit: every non-rigid label's lengths are whole multiples of it, in the outputs too.
expect_code 0 "$g2d" infer "$examples/2D Branches/T.json" --length-unit 0.5 -o tunit.g2d
has tunit.g2d 'unit = 0.5;'
expect_code 0 "$g2d" run tunit.g2d --json tunit.json --no-svg
python3 - tunit.json <<'PY' || fail "--length-unit 0.5: a length is not a whole multiple"
import json, math, sys
d = json.load(open(sys.argv[1]))
pos = {n["id"]: n["pos"] for n in d["nodes"]}
assert d["links"], "an empty output"
for l in d["links"]:
    (x0, y0), (x1, y1) = pos[l["source"]], pos[l["target"]]
    k = math.hypot(x1 - x0, y1 - y0) / 0.5
    assert abs(k - round(k)) < 1e-6 and round(k) >= 1, (l, k)
PY
expect_code 1 "$g2d" infer "$examples/2D Branches/T.json" --length-unit 0 -o zero_unit.g2d
has err.txt '--length-unit 0: lengths are whole multiples of it, so it must be positive'

# --connected: one starter, once; no removals; no application may split the output.
expect_code 0 "$g2d" infer "$examples/2D Networks/connected box.json" --connected -o cbox.g2d
has cbox.g2d 'priority -1 limit 1;   // one starter, once'
grep -q 'rule Stop' cbox.g2d && fail "--connected wrote a Stop rule"
has cbox.g2d 'connected = true;'
expect_code 0 "$g2d" check --werror cbox.g2d
# Pieces of a rule's side are asked to lie near each other.
expect_code 0 "$g2d" infer "$examples/2D Networks/connected box.json" -o box.g2d
grep -q 'where distance(x[0-9]*.pos, x[0-9]*.pos + ([-0-9.e]*, [-0-9.e]*)) <= [0-9.]* and distance(x[0-9]*.pos, x[0-9]*.pos - ' box.g2d || fail "connected box: no nearness condition"
# --no-loops: no loop glue, so no graph closes a loop and none is reduced by one (155 graphs become 1371).
expect_code 0 "$g2d" infer --stats "$examples/2D Networks/connected triangle.json"
with_loops=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["graphs"])' out.txt)
expect_code 0 "$g2d" infer --stats --no-loops "$examples/2D Networks/connected triangle.json"
without=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["graphs"])' out.txt)
[ "$without" != "$with_loops" ] || fail "--no-loops changed nothing: $without graphs"

# --bend: each label bends by its brush's Bend (T's brushes say 10 degrees), and the run's links are polylines.
expect_code 0 "$g2d" infer "$examples/2D Branches/T.json" --bend -o tbend.g2d
has tbend.g2d 'bend = radians(10);'
has tbend.g2d 'bend_segment = '
expect_code 0 "$g2d" check --werror tbend.g2d
expect_code 0 "$g2d" run tbend.g2d --seed 1 -D iterations=300 --json tbend.json -o tbend.svg
python3 - tbend.json <<'PY' || fail "--bend: no bent link in the output"
import json, sys
d = json.load(open(sys.argv[1]))
assert any(len(l.get("bend", [])) >= 2 for l in d["links"]), "no link has bend points"
PY
grep -q '<polyline' tbend.svg || fail "--bend: the SVG has no polyline"

# An output that cannot be written leaves nothing behind.
expect_code 1 "$g2d" infer "$examples/2D Branches/T.json" -o /nonexistent/dir/t.g2d
has err.txt 'g2d infer: error:'

finish
