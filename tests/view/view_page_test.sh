#!/usr/bin/env bash
# The --view page (a model in 3D, three.js inlined) in headless Chromium: its
# screenshot must show the model in the styles' colours (faces, and for the
# fan also edges and nodes); the page names no external URL; two runs, and
# a compiled program, write the same bytes. A copy of the page without its
# script must fail the same screenshot check, so the check can tell.
# Screenshots are kept in ARTIFACTS.
# Usage: view_page_test.sh G2D SOURCE_DIR ARTIFACTS [COMPILED]   (COMPILED=no: skip
# the compiled program, as sanitized builds do: building it there is slow)
set -u
g2d="$1"; src="$2"; artifacts="$3"; compiled="${4:-yes}"
source "$src/tests/cli/test_lib.sh"
command -v chromium >/dev/null || { echo "FAIL: chromium is not installed (scripts/install-deps.sh installs it)"; exit 1; }
# WebGL without a GPU: ANGLE on SwiftShader (newer Chromiums want it asked
# for by name). No host resolves, so the page cannot lean on the network.
chrome=(timeout 120 chromium --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader
        --host-resolver-rules="MAP * ~NOTFOUND" --hide-scrollbars --window-size=1000,700 --virtual-time-budget=5000)
mkdir -p "$artifacts"
shoot() {  # shoot PAGE PNG: a screenshot of PAGE after its scripts ran
  rm -f "$2"
  "${chrome[@]}" --screenshot="$2" "file://$work/$1" >/dev/null 2>&1
  [ -s "$2" ] || fail "no screenshot of $1"
}
# pixels PNG COLOURS...: as tests/view/png_colors.py counts them
pixels() { python3 "$src/tests/view/png_colors.py" "$@"; }

expect_code 0 "$g2d" run "$src/examples/subdivide.g2d" -D depth=2 --no-svg --view sub.html
expect_code 0 "$g2d" run "$src/examples/subdivide.g2d" -D depth=2 --no-svg --view again.html
cmp -s sub.html again.html || fail "two runs wrote different pages"
expect_code 0 "$g2d" run "$src/tests/view/fan_colours.g2d" --no-svg --view fan.html
# The same page from a compiled program (the same run driver).
if [ "$compiled" = yes ]; then
  expect_code 0 "$g2d" build "$src/examples/subdivide.g2d" -o subdivide
  expect_code 0 ./subdivide -D depth=2 --no-svg --view compiled.html
  cmp -s sub.html compiled.html || fail "the compiled program wrote another page than g2d run"
fi

# A face the page cannot triangulate: an error naming it, and no file written
# (the SVG neither: the page is made before any output is committed).
for bow in false true; do
  expect_code 1 "$g2d" run "$src/tests/view/undrawable_faces.g2d" -D bow=$bow -o u.svg --view u.html
  [ -e u.html ] || [ -e u.svg ] && fail "bow=$bow: a file was written"
done
want="face 0 (Wall, corners 0 1 2 3) cannot be drawn as triangles"
expect_code 1 "$g2d" run "$src/tests/view/undrawable_faces.g2d" -D bow=false --no-svg --view u.html
grep -qF "error: cannot write \`u.html\`: $want: its corners lie on one line, so it has no area" err.txt || fail "collinear: $(cat err.txt)"
expect_code 1 "$g2d" run "$src/tests/view/undrawable_faces.g2d" -D bow=true --no-svg --view u.html
grep -qF "error: cannot write \`u.html\`: $want: its outline crosses itself" err.txt || fail "bow tie: $(cat err.txt)"

# Self-contained: nothing loaded from elsewhere, the script inlined whole.
for page in sub.html fan.html; do
  if grep -Eiq '(src|href)[[:space:]]*=[[:space:]]*["'"'"']?[[:space:]]*(https?:)?//|<link|<iframe|@import|url\([[:space:]]*["'"'"']?https?:' "$page"; then
    fail "$page refers to an external resource"
  fi
  [ "$(grep -c '<script' "$page")" = 2 ] || fail "$page: expected the model and one inline script"
done
grep -q 'three.js\|Three.js' sub.html || fail "the page does not carry three.js"

# The model as data: 16 faces (depth 2), 25 nodes, 40 edges.
python3 - sub.html <<'PY' || fail "the model in the page"
import json, re, sys
page = open(sys.argv[1]).read()
m = json.loads(re.search(r'<script id="g2d-model" type="application/json">(.*?)</script>', page, re.S).group(1))
assert m["title"] == "subdivide.g2d", m["title"]
assert (len(m["nodes"]), len(m["edges"]), len(m["faces"])) == (25, 40, 16), (len(m["nodes"]), len(m["edges"]), len(m["faces"]))
# Each face: its id, colour, four corners' points and two triangles.
assert all(len(f[2]) == 12 and len(f[3]) == 6 for f in m["faces"]), "quads: four points, two triangles"
assert [f[0] for f in m["faces"]] == sorted({f[0] for f in m["faces"]}), "faces by id, once each"
assert all(n[3] == 0 for n in m["nodes"]), "P nodes have tag none: not drawn"
assert m["counts"] == {"nodes": 25, "edges": 40, "faces": 16}, m["counts"]
assert "25 nodes (0 drawn), 40 edges, 16 faces" in page
PY

shoot sub.html "$artifacts/view_subdivide.png"
shoot fan.html "$artifacts/view_fan.png"
# Without its script the page shows no model: the check below must say so.
python3 -c 'import sys; p = open(sys.argv[1]).read(); a = p.index("<script>") + 8; open(sys.argv[2], "w").write(p[:a] + p[p.rindex("</script>"):])' fan.html blank.html
shoot blank.html blank.png

# subdivide: its 16 face colours, read from the page, cover a good part of
# the picture and most of them show.
python3 - sub.html "$artifacts/view_subdivide.png" "$src/tests/view/png_colors.py" <<'PY' || fail "the subdivide screenshot"
import json, re, subprocess, sys
page, png, counter = sys.argv[1:4]
m = json.loads(re.search(r'<script id="g2d-model" type="application/json">(.*?)</script>', open(page).read(), re.S).group(1))
fills = sorted({m["colors"][f[1]] for f in m["faces"]})
r = json.loads(subprocess.check_output([sys.executable, counter, png] + fills))
total = r["width"] * r["height"]
shown = [c for c in fills if r["counts"][c] >= 300]
print("subdivide: %d of %d face colours shown, face pixels %.1f%%" % (len(shown), len(fills), 100 * r["matched"] / total))
assert len(fills) == 16 and len(shown) >= 14, r
assert r["matched"] >= 0.2 * total, r
PY

# The fan: faces green, edges red, nodes blue, each shows.
check_fan() {  # check_fan PNG: exit 0 when the fan shows
  python3 - "$1" "$src/tests/view/png_colors.py" <<'PY'
import json, subprocess, sys
r = json.loads(subprocess.check_output([sys.executable, sys.argv[2], sys.argv[1], "#2ca02c", "#d62728", "#1f77b4"]))
c, total = r["counts"], r["width"] * r["height"]
print("fan: faces %d, edges %d, nodes %d pixels of %d" % (c["#2ca02c"], c["#d62728"], c["#1f77b4"], total))
sys.exit(0 if c["#2ca02c"] >= 0.15 * total and c["#d62728"] >= 300 and c["#1f77b4"] >= 1000 else 1)
PY
}
check_fan "$artifacts/view_fan.png" || fail "the fan's screenshot does not show faces, edges and nodes"
check_fan blank.png >/dev/null && fail "the check passes a page without its script: it cannot tell"

# The script ran to its end (it clears the "needs WebGL" notice).
"${chrome[@]}" --dump-dom "file://$work/fan.html" 2>/dev/null | grep -q '<span id="status"></span>' \
  || fail "the page's script did not finish (WebGL missing, or an error)"
finish
