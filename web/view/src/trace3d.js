// The player of a 3D grammar's trace (`g2d run --trace OUT.html`; the format
// is docs/trace.md's, nodes [id, kind, x, y, z], faces with their triangles
// as node ids): any step rebuilt from the deltas and drawn by the viewer the
// --view page uses, in each kind's style, with the step's highlights:
// orange matched and kept, red deleted (where they were), green added, blue
// moved. The page (trace_page.cpp) gives the controls: #first, #prev, #play,
// #next, #last, #slider, #position, #info, #note, in #legend.
import { playerControls, traceFrames } from "./trace_state.js";

const COLORS = { added: "#1a9e3a", deleted: "#d62728", matched: "#ff8c00", moved: "#1f77b4" };

// `viewer` (viewer.js) draws the frames; the page gives it.
export function playTrace(trace, viewer) {
  const frames = traceFrames(trace);
  const { stateAt, marks, frameCount, perFrame, steps, lo, hi } = frames;
  const diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1;
  const dot = 0.006 * diagonal;   // a node's radius when its style gives none, as on the --view page

  // The model of a frame, in the viewer's form (viewer.js).
  function modelOf(state, before, m) {
    const colors = [], colorIndex = new Map();
    const color = (css) => {
      if (!css || css === "none") return -1;
      if (!colorIndex.has(css)) colorIndex.set(css, colors.length), colors.push(css);
      return colorIndex.get(css);
    };
    const markOf = (key) => (m.added.has(key) ? "added" : m.moved.has(key) ? "moved" : m.matched.has(key) ? "matched" : "");
    const model = { colors, nodes: [], edges: [], faces: [], faceAlphas: [] };
    const index = new Map();   // "state:id" -> index into model.nodes
    const at = (which, nodes, id) => {
      const key = which + id;
      if (!index.has(key)) {
        const n = nodes.get(id);
        index.set(key, model.nodes.length);
        model.nodes.push([n.x, n.y, n.z, 0, -1]);
      }
      return index.get(key);
    };
    const addNode = (which, nodes, id, mark) => {
      const style = trace.kinds[nodes.get(id).kind].style;
      if (style.tag === "none" && !mark) return;
      const i = at(which, nodes, id);
      model.nodes[i][3] = style.tag === "circle" ? style.r : dot * (mark ? 1.5 : 1);
      model.nodes[i][4] = color(mark ? COLORS[mark] : style.fill !== "none" ? style.fill : style.stroke);
    };
    const addEdge = (which, nodes, e, mark) => {
      const style = trace.kinds[e.kind].style;
      if ((style.tag === "none" && !mark) || !nodes.has(e.src) || !nodes.has(e.dst)) return;
      // Marked edges as thin tubes, so that they show.
      model.edges.push([at(which, nodes, e.src), at(which, nodes, e.dst), color(mark ? COLORS[mark] : style.stroke), mark ? dot / 2 : 0]);
    };
    const addFace = (nodes, id, f, mark) => {
      const style = trace.kinds[f.kind].style;
      if ((style.tag === "none" && !mark) || f.triangles.some((n) => !nodes.has(n))) return;
      const order = [...new Set(f.triangles)], points = order.flatMap((n) => [nodes.get(n).x, nodes.get(n).y, nodes.get(n).z]);
      const tris = f.triangles.map((n) => order.indexOf(n));
      model.faces.push([id, color(mark ? COLORS[mark] : style.fill !== "none" ? style.fill : "#d9d9d9"), points, tris]);
      model.faceAlphas.push(mark === "deleted" ? 0.35 : 1);
    };
    for (const [id, f] of state.faces) addFace(state.nodes, id, f, markOf("f" + id));
    for (const [id, f] of before.faces) if (m.deleted.has("f" + id)) addFace(before.nodes, id, f, "deleted");
    for (const [id, e] of state.edges) addEdge("s", state.nodes, e, markOf("e" + id));
    for (const [id, e] of before.edges) if (m.deleted.has("e" + id)) addEdge("b", before.nodes, e, "deleted");
    for (const [id] of state.nodes) addNode("s", state.nodes, id, markOf("n" + id));
    for (const [id] of before.nodes) if (m.deleted.has("n" + id)) addNode("b", before.nodes, id, "deleted");
    return model;
  }

  function draw(frame) {
    const state = stateAt(frame), before = frame > 0 ? stateAt(frame - 1) : state, m = marks(frame);
    viewer.draw(modelOf(state, before, m));
    document.getElementById("info").textContent =
      frames.describe(frame, m) + ` Graph: ${state.nodes.size} nodes, ${state.edges.size} edges, ${state.faces.size} faces.`;
    window.g2dTrace.frame = frame;
    window.g2dTrace.drawn = { nodes: state.nodes.size, edges: state.edges.size, faces: state.faces.size,
      matched: m.matched.size, deleted: m.deleted.size, added: m.added.size, moved: m.moved.size,
      triangles: viewer.drawn.triangles };
  }
  window.g2dTrace = { frameCount, perFrame, steps: steps.length, frame: 0, drawn: null, viewer };
  window.g2dTrace.go = playerControls(frames, draw);
  window.g2dTrace.go(frameCount);
  viewer.frame(lo, hi, [1, -2, 1.5]);   // from where the SVG of a 3D grammar looks by default
}
