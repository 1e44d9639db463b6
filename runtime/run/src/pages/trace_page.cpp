// The page of `g2d run --trace OUT.html`: one self-contained file (no
// network), the trace embedded as JSON, the final SVG as g2d draws it, and a
// player that rebuilds any step from the deltas. Steps past kMaxFrames are
// grouped into frames so the slider stays usable; the page says so.
#include "g2d/trace.hpp"

#include "g2d/svg_writer.hpp"
#include "g2d/view_script.hpp"

namespace g2d::rt {

namespace {

// Inside <script>, "</" would end the element.
std::string scriptSafe(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '<' && i + 1 < s.size() && s[i + 1] == '/') out += "<\\";
        else out += s[i];
    }
    return out;
}

const char* const kStyle = R"CSS(
body { font: 14px system-ui, sans-serif; margin: 0; color: #222; }
header { padding: 8px 12px; background: #f4f4f4; border-bottom: 1px solid #ddd; }
main { display: flex; flex-wrap: wrap; gap: 12px; padding: 12px; }
section { flex: 1 1 420px; min-width: 320px; }
h2 { font-size: 15px; margin: 0 0 6px; }
#stage, #final svg { width: 100%; height: 60vh; border: 1px solid #ddd; background: white; }
#controls { display: flex; align-items: center; gap: 6px; margin: 8px 0; }
#slider { flex: 1; }
#info { min-height: 3em; }
#note { color: #8a5a00; }
.legend span { display: inline-block; margin-right: 12px; }
.sw { display: inline-block; width: 12px; height: 12px; vertical-align: middle; margin-right: 4px; }
)CSS";

const char* const kScript = R"JS(
"use strict";
const trace = JSON.parse(document.getElementById("trace").textContent);
const MAX_FRAMES = 2000;
const steps = trace.steps;
const perFrame = Math.max(1, Math.ceil(steps.length / MAX_FRAMES));
const frameCount = Math.ceil(steps.length / perFrame);   // frame f (1..) ends with step min(f*perFrame, n)
const COLORS = { added: "#1a9e3a", deleted: "#d62728", matched: "#ff8c00", moved: "#1f77b4" };
const SVGNS = "http://www.w3.org/2000/svg";

function emptyState() { return { nodes: new Map(), edges: new Map(), faces: new Map() }; }
function copyState(s) { return { nodes: new Map(s.nodes), edges: new Map(s.edges), faces: new Map(s.faces) }; }
function applyStep(state, st) {
  for (const id of st.deleted.faces || []) state.faces.delete(id);
  for (const id of st.deleted.edges) state.edges.delete(id);
  for (const id of st.deleted.nodes) state.nodes.delete(id);
  for (const [id, kind, x, y] of st.added.nodes) state.nodes.set(id, { kind, x, y });
  for (const [id, kind, x, y] of st.moved) state.nodes.set(id, { kind, x, y });
  for (const [id, kind, src, dst] of st.added.edges) state.edges.set(id, { kind, src, dst });
  for (const [id, kind, src, dst] of st.rewired) state.edges.set(id, { kind, src, dst });
  for (const [id, kind, corners] of st.added.faces || []) state.faces.set(id, { kind, corners });
}

const axiom = emptyState();
for (const [id, kind, x, y] of trace.axiom.nodes) axiom.nodes.set(id, { kind, x, y });
for (const [id, kind, src, dst] of trace.axiom.edges) axiom.edges.set(id, { kind, src, dst });
for (const [id, kind, corners] of trace.axiom.faces || []) axiom.faces.set(id, { kind, corners });

// Snapshots every 50 frames, made on the way, so that seeking stays quick.
const checkpoints = new Map([[0, copyState(axiom)]]);
function stateAt(frame) {
  let from = 0;
  for (const f of checkpoints.keys()) if (f <= frame && f > from) from = f;
  const state = copyState(checkpoints.get(from));
  for (let f = from + 1; f <= frame; f++) {
    for (let i = (f - 1) * perFrame; i < Math.min(f * perFrame, steps.length); i++) applyStep(state, steps[i]);
    if (f % 50 === 0 && !checkpoints.has(f)) checkpoints.set(f, copyState(state));
  }
  return state;
}

// One frame's highlights: what its steps matched (and kept), deleted, added and moved.
function marks(frame) {
  const m = { matched: new Set(), deleted: new Set(), added: new Set(), moved: new Set() };
  if (frame === 0) return m;
  for (let i = (frame - 1) * perFrame; i < Math.min(frame * perFrame, steps.length); i++) {
    const st = steps[i];
    st.matched.nodes.forEach((id) => m.matched.add("n" + id));
    st.matched.edges.forEach((id) => m.matched.add("e" + id));
    (st.matched.faces || []).forEach((id) => m.matched.add("f" + id));
    (st.deleted.faces || []).forEach((id) => m.deleted.add("f" + id));
    ((st.added.faces) || []).forEach(([id]) => m.added.add("f" + id));
    st.deleted.nodes.forEach((id) => m.deleted.add("n" + id));
    st.deleted.edges.forEach((id) => m.deleted.add("e" + id));
    st.added.nodes.forEach(([id]) => m.added.add("n" + id));
    st.added.edges.forEach(([id]) => m.added.add("e" + id));
    st.moved.forEach(([id]) => m.moved.add("n" + id));
  }
  for (const key of m.deleted) m.matched.delete(key);   // "matched" means matched and kept
  return m;
}

// A fixed frame: every place any node ever takes.
let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
function grow(x, y) { x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y); }
trace.axiom.nodes.forEach(([, , x, y]) => grow(x, y));
steps.forEach((st) => { st.added.nodes.forEach(([, , x, y]) => grow(x, y)); st.moved.forEach(([, , x, y]) => grow(x, y)); });
if (!isFinite(x0)) { x0 = y0 = 0; x1 = y1 = 1; }
const size = Math.max(x1 - x0, y1 - y0, 1e-3), pad = 0.05 * size;
const stage = document.getElementById("stage");
stage.setAttribute("viewBox", `${x0 - pad} ${-(y1 + pad)} ${x1 - x0 + 2 * pad} ${y1 - y0 + 2 * pad}`);
const unit = size / 400;   // highlight widths, in drawing units

function el(name, attrs) {
  const e = document.createElementNS(SVGNS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  return e;
}

function draw(frame) {
  const state = stateAt(frame), before = frame > 0 ? stateAt(frame - 1) : state, m = marks(frame);
  const layer = el("g", { transform: "scale(1 -1)" });
  const markOf = (key) => (m.added.has(key) ? "added" : m.moved.has(key) ? "moved" : m.matched.has(key) ? "matched" : "");
  const drawEdge = (id, e, nodes, mark) => {
    const a = nodes.get(e.src), b = nodes.get(e.dst);
    if (!a || !b) return;
    const style = trace.kinds[e.kind].style;
    if (style.tag === "none" && !mark) return;
    const width = mark ? Math.max(style.stroke_width * 2, 3 * unit) : style.stroke_width;
    layer.appendChild(el("line", { x1: a.x, y1: a.y, x2: b.x, y2: b.y, stroke: mark ? COLORS[mark] : style.stroke,
      "stroke-width": width, "stroke-dasharray": mark === "deleted" ? `${4 * unit} ${3 * unit}` : "none",
      "data-id": "e" + id, class: "edge " + mark }));
  };
  const drawNode = (id, n, mark) => {
    const style = trace.kinds[n.kind].style;
    if (style.tag === "none" && !mark) return;
    const r = style.tag === "none" ? 3 * unit : Math.max(style.r, mark ? 3 * unit : 0);
    layer.appendChild(el("circle", { cx: n.x, cy: n.y, r, fill: mark ? COLORS[mark] : style.fill,
      stroke: mark ? COLORS[mark] : style.stroke, "stroke-width": style.stroke_width,
      "data-id": "n" + id, class: "node " + mark }));
  };
  // Faces below edges and nodes, as the SVG draws them.
  const drawFace = (id, f, nodes, mark) => {
    const points = f.corners.map((c) => nodes.get(c));
    if (points.some((p) => !p)) return;
    const style = trace.kinds[f.kind].style;
    if (style.tag === "none" && !mark) return;
    layer.appendChild(el("polygon", { points: points.map((p) => `${p.x},${p.y}`).join(" "),
      fill: style.fill, "fill-opacity": mark === "deleted" ? 0.35 : 1,
      stroke: mark ? COLORS[mark] : style.stroke, "stroke-width": mark ? 3 * unit : style.stroke_width,
      "stroke-dasharray": mark === "deleted" ? `${4 * unit} ${3 * unit}` : "none",
      "data-id": "f" + id, class: "face " + mark }));
  };
  for (const [id, f] of state.faces) drawFace(id, f, state.nodes, markOf("f" + id));
  for (const [id, f] of before.faces) if (m.deleted.has("f" + id)) drawFace(id, f, before.nodes, "deleted");
  for (const [id, e] of state.edges) drawEdge(id, e, state.nodes, markOf("e" + id));
  for (const [id, e] of before.edges) if (m.deleted.has("e" + id)) drawEdge(id, e, before.nodes, "deleted");
  for (const [id, n] of state.nodes) drawNode(id, n, markOf("n" + id));
  for (const [id, n] of before.nodes) if (m.deleted.has("n" + id)) drawNode(id, n, "deleted");
  stage.replaceChildren(layer);

  const info = document.getElementById("info");
  if (frame === 0) {
    info.textContent = `The axiom: ${state.nodes.size} nodes, ${state.edges.size} edges.`;
  } else {
    const first = (frame - 1) * perFrame, last = Math.min(frame * perFrame, steps.length) - 1;
    const st = steps[last];
    const rules = new Set(steps.slice(first, last + 1).map((s) => s.rule));
    const daughters = st.daughters.map((d) => d + 1).join(", ");
    info.textContent = (first === last ? `Step ${st.step}: production ${st.rule}, daughter ${daughters}` +
                                         (st.daughters.length > 1 ? ` (${st.daughters.length} rewrites at once)` : "")
                                       : `Steps ${steps[first].step}–${st.step}: ${[...rules].join(", ")}`) +
      `. ${m.matched.size} matched and kept, ${m.deleted.size} deleted, ${m.added.size} added, ${m.moved.size} moved. ` +
      `Graph: ${state.nodes.size} nodes, ${state.edges.size} edges.`;
  }
  document.getElementById("slider").value = frame;
  document.getElementById("position").textContent = `${frame} / ${frameCount}`;
  current = frame;
  window.g2dTrace.frame = frame;
  window.g2dTrace.drawn = { nodes: state.nodes.size, edges: state.edges.size,
    matched: m.matched.size, deleted: m.deleted.size, added: m.added.size, moved: m.moved.size };
}

let current = 0, timer = null;
const slider = document.getElementById("slider");
slider.max = frameCount;
slider.addEventListener("input", () => draw(Number(slider.value)));
const go = (f) => draw(Math.max(0, Math.min(frameCount, f)));
document.getElementById("first").onclick = () => go(0);
document.getElementById("prev").onclick = () => go(current - 1);
document.getElementById("next").onclick = () => go(current + 1);
document.getElementById("last").onclick = () => go(frameCount);
document.getElementById("play").onclick = () => {
  const button = document.getElementById("play");
  if (timer) { clearInterval(timer); timer = null; button.textContent = "Play"; return; }
  if (current >= frameCount) go(0);
  button.textContent = "Pause";
  timer = setInterval(() => {
    if (current >= frameCount) { clearInterval(timer); timer = null; button.textContent = "Play"; return; }
    go(current + 1);
  }, Math.max(20, 4000 / Math.max(frameCount, 1)));
};
document.addEventListener("keydown", (e) => {
  if (e.key === "ArrowRight") go(current + 1);
  if (e.key === "ArrowLeft") go(current - 1);
});
if (perFrame > 1)
  document.getElementById("note").textContent =
    `This run has ${steps.length} steps: the timeline is thinned to ${frameCount} frames of ${perFrame} steps each ` +
    `(highlights show all of a frame's steps).`;
window.g2dTrace = { frameCount, perFrame, steps: steps.length, go, frame: 0, drawn: null };
go(frameCount);
)JS";

// The 3D player: the viewer fills the window, the controls float over it.
const char* const kStyle3d = R"CSS(
html, body { margin: 0; height: 100%; overflow: hidden; background: #fff; font: 13px system-ui, sans-serif; color: #222; }
canvas { display: block; }
#legend { position: absolute; top: 8px; left: 8px; padding: 6px 10px; max-width: 46em;
  background: rgba(255, 255, 255, 0.85); border: 1px solid #ddd; border-radius: 4px; }
#controls { display: flex; align-items: center; gap: 6px; margin: 6px 0; }
#slider { flex: 1; }
#note, #status { color: #8a5a00; }
#toggles, #views { margin-top: 4px; }
.legend span { display: inline-block; margin-right: 12px; }
.sw { display: inline-block; width: 12px; height: 12px; vertical-align: middle; margin-right: 4px; }
small { display: block; color: #666; margin-top: 2px; }
)CSS";

const char* const kControls =
    "<div id=\"controls\"><button id=\"first\">|&lt;</button><button id=\"prev\">&lt;</button>"
    "<button id=\"play\">Play</button><button id=\"next\">&gt;</button><button id=\"last\">&gt;|</button>"
    "<input id=\"slider\" type=\"range\" min=\"0\" value=\"0\"><span id=\"position\"></span></div>\n";

const char* const kMarks =
    "<p class=\"legend\">"
    "<span><i class=\"sw\" style=\"background:#ff8c00\"></i>matched and kept</span>"
    "<span><i class=\"sw\" style=\"background:#d62728\"></i>deleted</span>"
    "<span><i class=\"sw\" style=\"background:#1a9e3a\"></i>added</span>"
    "<span><i class=\"sw\" style=\"background:#1f77b4\"></i>moved</span></p>\n";

std::string tracePage3d(const std::string& traceJson, const std::string& title) {
    std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + xmlEscape(title) +
                      " — g2d trace</title>\n<style>" + kStyle3d + "</style>\n</head>\n<body>\n";
    out += "<div id=\"legend\"><strong>" + xmlEscape(title) + "</strong> — derivation trace (g2d), in 3D\n" + kControls;
    out += "<div id=\"info\"></div>\n<div id=\"note\"></div>\n" + std::string(kMarks) +
           "<small>Steps are drawn with each kind's style. Drag to turn, right-drag to pan, scroll to zoom; "
           "arrow keys step.</small><span id=\"status\">This page needs JavaScript and WebGL.</span></div>\n";
    out += "<script id=\"trace\" type=\"application/json\">" + scriptSafe(traceJson) + "</script>\n";
    out += "<script>" + viewScript() + "</script>\n</body>\n</html>\n";
    return out;
}

}  // namespace

std::string writeTracePage(const std::string& traceJson, const std::string& finalSvg, const std::string& title, bool space3d) {
    if (space3d) return tracePage3d(traceJson, title);
    // The final SVG goes inline without its XML declaration.
    std::string svg = finalSvg;
    if (svg.rfind("<?xml", 0) == 0) svg = svg.substr(svg.find('\n') + 1);
    std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + xmlEscape(title) +
                      " — g2d trace</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
    out += "<header><strong>" + xmlEscape(title) + "</strong> — derivation trace (g2d)</header>\n<main>\n";
    out += "<section>\n<h2>Step by step</h2>\n<svg id=\"stage\" xmlns=\"http://www.w3.org/2000/svg\"></svg>\n";
    out += kControls;
    out += "<div id=\"info\"></div>\n<div id=\"note\"></div>\n" + std::string(kMarks) +
           "<p>Steps are drawn with each kind's style; the final drawing, as g2d writes it, is on the right.</p>\n</section>\n";
    out += "<section id=\"final\">\n<h2>Final drawing</h2>\n" + svg + "</section>\n</main>\n";
    out += "<script id=\"trace\" type=\"application/json\">" + scriptSafe(traceJson) + "</script>\n";
    out += std::string("<script>") + kScript + "</script>\n</body>\n</html>\n";
    return out;
}

}  // namespace g2d::rt
