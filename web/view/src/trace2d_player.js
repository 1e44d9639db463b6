// The player of a 2D grammar's trace (`g2d run --trace OUT.html`,
// runtime/run/src/pages/trace_page.cpp, and the studio; format in docs/trace.md): any step
// rebuilt from the deltas (trace_state.js) and drawn as SVG in each kind's
// style, with the step's highlights: orange matched and kept, dashed red
// deleted (where they were), green added, blue moved.
import { playerControls, traceFrames } from "./trace_state.js";

const COLORS = { added: "#1a9e3a", deleted: "#d62728", matched: "#ff8c00", moved: "#1f77b4" };
const SVGNS = "http://www.w3.org/2000/svg";

function el(name, attrs) {
  const e = document.createElementNS(SVGNS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  return e;
}

// Plays `trace` in the <svg> `stage`, describing each frame in `info`.
// Returns the player's `go` (trace_state.js).
export function playTrace2d(trace, stage, info) {
  const frames = traceFrames(trace);
  const { stateAt, marks, frameCount, perFrame, steps } = frames;

  // A fixed frame: every place any node ever takes.
  const [x0, y0] = frames.lo, [x1, y1] = frames.hi;
  const size = Math.max(x1 - x0, y1 - y0, 1e-3), pad = 0.05 * size;
  stage.setAttribute("viewBox", `${x0 - pad} ${-(y1 + pad)} ${x1 - x0 + 2 * pad} ${y1 - y0 + 2 * pad}`);
  const unit = size / 400;   // highlight widths, in drawing units


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

    const graph = `Graph: ${state.nodes.size} nodes, ${state.edges.size} edges.`;
    info.textContent =
      frame === 0 ? `The axiom: ${state.nodes.size} nodes, ${state.edges.size} edges.` : frames.describe(frame, m) + " " + graph;
    window.g2dTrace.frame = frame;
    window.g2dTrace.drawn = { nodes: state.nodes.size, edges: state.edges.size,
      matched: m.matched.size, deleted: m.deleted.size, added: m.added.size, moved: m.moved.size };
  }

  window.g2dTrace = { frameCount, perFrame, steps: steps.length, frame: 0, drawn: null };
  window.g2dTrace.go = playerControls(frames, draw);
  window.g2dTrace.go(frameCount);
  return window.g2dTrace.go;
}
