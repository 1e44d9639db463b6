#!/usr/bin/env bash
# The --trace page in headless Chromium (Debian's chromium): a harness page
# steps through it (slider positions, the Next button) and reports what is
# drawn; a long run shows a thinned timeline and says so; a screenshot of
# the page is kept in ARTIFACTS.
# Usage: trace_page_test.sh G2D SOURCE_DIR ARTIFACTS
set -u
g2d="$1"; src="$2"; artifacts="$3"
source "$src/tests/cli/test_lib.sh"
command -v chromium >/dev/null || { echo "FAIL: chromium is not installed (scripts/install-deps.sh installs it)"; exit 1; }
browse() {  # the DOM of a page after its scripts ran
  timeout 120 chromium --headless --no-sandbox --disable-gpu --allow-file-access-from-files \
    --virtual-time-budget=10000 --dump-dom "file://$work/$1" 2>/dev/null
}

expect_code 0 "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=2 -o koch.svg --trace koch.html
expect_code 0 "$g2d" run "$src/examples/koch_snowflake.g2d" -D max_lod=6 --no-svg --trace long.html

cat > harness.html <<'HTML'
<!DOCTYPE html><html><body><pre id="result">pending</pre>
<iframe id="koch" src="koch.html" width="1000" height="700"></iframe>
<iframe id="long" src="long.html" width="1000" height="700"></iframe>
<script>
let loaded = 0;
const report = {};
function probe(name) {
  const w = document.getElementById(name).contentWindow, d = w.document, t = w.g2dTrace;
  const look = () => ({ frame: t.frame, info: d.getElementById("info").textContent,
    lines: d.querySelectorAll("#stage line").length, circles: d.querySelectorAll("#stage circle").length,
    added: d.querySelectorAll("#stage .added").length, deleted: d.querySelectorAll("#stage .deleted").length,
    matched: d.querySelectorAll("#stage .matched").length });
  const r = { frameCount: t.frameCount, perFrame: t.perFrame, steps: t.steps, note: d.getElementById("note").textContent,
              finalSvg: d.querySelectorAll("#final svg line").length, atLoad: look() };
  t.go(0); r.axiom = look();
  d.getElementById("next").click(); r.next = look();
  d.getElementById("next").click(); r.next2 = look();
  d.getElementById("prev").click(); r.prev = look();
  const slider = d.getElementById("slider");
  slider.value = String(t.frameCount); slider.dispatchEvent(new Event("input")); r.slidEnd = look();
  d.getElementById("next").click(); r.pastEnd = look();
  return r;
}
for (const name of ["koch", "long"])
  document.getElementById(name).addEventListener("load", () => {
    try { report[name] = probe(name); } catch (e) { report[name] = { error: String(e) }; }
    if (++loaded === 2) document.getElementById("result").textContent = JSON.stringify(report);
  });
</script></body></html>
HTML
browse harness.html > dom.html
python3 - dom.html <<'PY' || fail "the page in Chromium"
import html, json, re, sys
m = re.search(r'<pre id="result">(.*?)</pre>', open(sys.argv[1]).read(), re.S)
assert m and m.group(1) != "pending", "the harness did not finish"
r = json.loads(html.unescape(m.group(1)))
k, l = r["koch"], r["long"]
assert "error" not in k and "error" not in l, r
# Koch level 2: 15 steps, one frame each, 48 edges at the end (the final SVG too).
assert k["frameCount"] == 15 and k["perFrame"] == 1 and k["note"] == "", k
assert k["finalSvg"] == 48, k["finalSvg"]
assert k["atLoad"]["frame"] == 15 and k["atLoad"]["lines"] == 48 + 1, k["atLoad"]   # plus the deleted edge, dashed
assert k["axiom"] == {"frame": 0, "info": "The axiom: 3 nodes, 3 edges.", "lines": 3, "circles": 0, "added": 0, "deleted": 0, "matched": 0}, k["axiom"]
n = k["next"]
# Step 1 splits one edge: it is drawn deleted, its two ends matched, 3 nodes + 4 edges added.
assert n["frame"] == 1 and n["info"].startswith("Step 1: production Split, daughter 1. 2 matched and kept, 1 deleted, 7 added"), n
assert (n["lines"], n["deleted"], n["matched"], n["added"]) == (6 + 1, 1, 2, 7), n
assert k["next2"]["frame"] == 2 and k["next2"]["lines"] == 9 + 1, k["next2"]
assert k["prev"]["frame"] == 1 and k["prev"] == n, k["prev"]
assert k["slidEnd"]["frame"] == 15 and k["pastEnd"]["frame"] == 15, (k["slidEnd"], k["pastEnd"])
# Level 6: 4095 steps thinned to frames of 3 steps, and the page says so.
assert l["steps"] == 4095 and l["perFrame"] == 3 and l["frameCount"] == 1365, l
assert "thinned to 1365 frames of 3 steps" in l["note"], l["note"]
assert l["next"]["info"].startswith("Steps 1–3: Split."), l["next"]
assert l["atLoad"]["lines"] >= 3 * 4 ** 6, l["atLoad"]
print("page checks passed")
PY

# Faces: the axiom's twelve panes as polygons; a split draws the pane it
# deletes dashed and the two it adds marked.
expect_code 0 "$g2d" run "$src/examples/stained_glass.g2d" -D smallest=0.2 -o glass.svg --trace glass.html
cat > faces.html <<'HTML'
<!DOCTYPE html><html><body><pre id="result">pending</pre>
<iframe id="glass" src="glass.html" width="1000" height="700"></iframe>
<script>
document.getElementById("glass").addEventListener("load", () => {
  const w = document.getElementById("glass").contentWindow, d = w.document, t = w.g2dTrace;
  const look = () => ({ frame: t.frame, polygons: d.querySelectorAll("#stage polygon").length,
    added: d.querySelectorAll("#stage polygon.added").length, deleted: d.querySelectorAll("#stage polygon.deleted").length });
  const r = {};
  try {
    t.go(0); r.axiom = look();
    d.getElementById("next").click(); r.next = look();
  } catch (e) { r.error = String(e); }
  document.getElementById("result").textContent = JSON.stringify(r);
});
</script></body></html>
HTML
browse faces.html > faces_dom.html
python3 - faces_dom.html <<'PY' || fail "faces in the page"
import html, json, re, sys
m = re.search(r'<pre id="result">(.*?)</pre>', open(sys.argv[1]).read(), re.S)
assert m and m.group(1) != "pending", "the harness did not finish"
r = json.loads(html.unescape(m.group(1)))
assert "error" not in r, r
assert r["axiom"] == {"frame": 0, "polygons": 12, "added": 0, "deleted": 0}, r["axiom"]
assert r["next"] == {"frame": 1, "polygons": 13 + 1, "added": 2, "deleted": 1}, r["next"]
print("face checks passed")
PY

# A screenshot of the page, kept as a test artefact.
mkdir -p "$artifacts"
rm -f "$artifacts/trace_page.png"
timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1280,900 \
  --virtual-time-budget=5000 --screenshot="$artifacts/trace_page.png" "file://$work/koch.html" >/dev/null 2>&1
[ "$(head -c 8 "$artifacts/trace_page.png" 2>/dev/null | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] \
  && [ "$(stat -c %s "$artifacts/trace_page.png")" -gt 10000 ] || fail "no screenshot in $artifacts/trace_page.png"
finish
