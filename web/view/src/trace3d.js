// The player of a 3D grammar's trace (`g2d run --trace OUT.html`; the format
// is docs/trace.md's, nodes [id, kind, x, y, z], faces with their triangles
// as node ids): any step rebuilt from the deltas and drawn by the viewer the
// --view page uses, in each kind's style, with the step's highlights:
// orange matched and kept, red deleted (where they were), green added, blue
// moved. The page (trace_page.cpp) gives the controls: #first, #prev, #play,
// #next, #last, #slider, #position, #info, #note, in #legend.
const MAX_FRAMES = 2000;
const COLORS = { added: "#1a9e3a", deleted: "#d62728", matched: "#ff8c00", moved: "#1f77b4" };

function emptyState() {
  return { nodes: new Map(), edges: new Map(), faces: new Map() };
}
function copyState(s) {
  return { nodes: new Map(s.nodes), edges: new Map(s.edges), faces: new Map(s.faces) };
}
const node = ([, kind, x, y, z]) => ({ kind, p: [x, y, z || 0] });
const edge = ([, kind, src, dst]) => ({ kind, src, dst });
const face = ([, kind, corners, triangles]) => ({ kind, corners, triangles: triangles || [] });

function applyStep(state, st) {
  for (const id of st.deleted.faces || []) state.faces.delete(id);
  for (const id of st.deleted.edges) state.edges.delete(id);
  for (const id of st.deleted.nodes) state.nodes.delete(id);
  for (const n of st.added.nodes) state.nodes.set(n[0], node(n));
  for (const n of st.moved) state.nodes.set(n[0], node(n));
  for (const e of st.added.edges) state.edges.set(e[0], edge(e));
  for (const e of st.rewired) state.edges.set(e[0], edge(e));
  for (const f of st.added.faces || []) state.faces.set(f[0], face(f));
}

export function playTrace(trace, createViewer) {
  const steps = trace.steps;
  const perFrame = Math.max(1, Math.ceil(steps.length / MAX_FRAMES));
  const frameCount = Math.ceil(steps.length / perFrame);   // frame f (1..) ends with step min(f*perFrame, n)
  const axiom = emptyState();
  for (const n of trace.axiom.nodes) axiom.nodes.set(n[0], node(n));
  for (const e of trace.axiom.edges) axiom.edges.set(e[0], edge(e));
  for (const f of trace.axiom.faces || []) axiom.faces.set(f[0], face(f));

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
    for (let i = (frame - 1) * perFrame; frame > 0 && i < Math.min(frame * perFrame, steps.length); i++) {
      const st = steps[i];
      st.matched.nodes.forEach((id) => m.matched.add("n" + id));
      st.matched.edges.forEach((id) => m.matched.add("e" + id));
      (st.matched.faces || []).forEach((id) => m.matched.add("f" + id));
      st.deleted.nodes.forEach((id) => m.deleted.add("n" + id));
      st.deleted.edges.forEach((id) => m.deleted.add("e" + id));
      (st.deleted.faces || []).forEach((id) => m.deleted.add("f" + id));
      st.added.nodes.forEach(([id]) => m.added.add("n" + id));
      st.added.edges.forEach(([id]) => m.added.add("e" + id));
      (st.added.faces || []).forEach(([id]) => m.added.add("f" + id));
      st.moved.forEach(([id]) => m.moved.add("n" + id));
    }
    for (const key of m.deleted) m.matched.delete(key);   // "matched" means matched and kept
    return m;
  }

  // A fixed frame: every place any node ever takes.
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  const grow = (n) => node(n).p.forEach((v, i) => ((lo[i] = Math.min(lo[i], v)), (hi[i] = Math.max(hi[i], v))));
  trace.axiom.nodes.forEach(grow);
  steps.forEach((st) => (st.added.nodes.forEach(grow), st.moved.forEach(grow)));
  if (!isFinite(lo[0])) lo.fill(-1), hi.fill(1);
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
        model.nodes.push([...n.p, 0, -1]);
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
      const order = [...new Set(f.triangles)], points = order.flatMap((n) => nodes.get(n).p);
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

  const $ = (id) => document.getElementById(id);
  const viewer = createViewer({ panel: $("legend"), key: "trace:" + trace.grammar });
  let current = 0, timer = null;
  function draw(frame) {
    const state = stateAt(frame), before = frame > 0 ? stateAt(frame - 1) : state, m = marks(frame);
    viewer.draw(modelOf(state, before, m));
    const counts = `Graph: ${state.nodes.size} nodes, ${state.edges.size} edges, ${state.faces.size} faces.`;
    if (frame === 0) {
      $("info").textContent = "The axiom. " + counts;
    } else {
      const first = (frame - 1) * perFrame, last = Math.min(frame * perFrame, steps.length) - 1;
      const st = steps[last];
      const rules = new Set(steps.slice(first, last + 1).map((s) => s.rule));
      const daughters = st.daughters.map((d) => d + 1).join(", ");
      $("info").textContent = (first === last ? `Step ${st.step}: production ${st.rule}, daughter ${daughters}` +
                                                (st.daughters.length > 1 ? ` (${st.daughters.length} rewrites at once)` : "")
                                              : `Steps ${steps[first].step}–${st.step}: ${[...rules].join(", ")}`) +
        `. ${m.matched.size} matched and kept, ${m.deleted.size} deleted, ${m.added.size} added, ${m.moved.size} moved. ` + counts;
    }
    $("slider").value = frame;
    $("position").textContent = `${frame} / ${frameCount}`;
    current = frame;
    window.g2dTrace.frame = frame;
    window.g2dTrace.drawn = { nodes: state.nodes.size, edges: state.edges.size, faces: state.faces.size,
      matched: m.matched.size, deleted: m.deleted.size, added: m.added.size, moved: m.moved.size,
      triangles: viewer.drawn.triangles };
  }

  const go = (f) => draw(Math.max(0, Math.min(frameCount, f)));
  const slider = $("slider");
  slider.max = frameCount;
  slider.addEventListener("input", () => draw(Number(slider.value)));
  $("first").onclick = () => go(0);
  $("prev").onclick = () => go(current - 1);
  $("next").onclick = () => go(current + 1);
  $("last").onclick = () => go(frameCount);
  $("play").onclick = () => {
    const button = $("play");
    if (timer) return clearInterval(timer), (timer = null), (button.textContent = "Play");
    if (current >= frameCount) go(0);
    button.textContent = "Pause";
    timer = setInterval(() => {
      if (current >= frameCount) return clearInterval(timer), (timer = null), (button.textContent = "Play");
      go(current + 1);
    }, Math.max(20, 4000 / Math.max(frameCount, 1)));
  };
  document.addEventListener("keydown", (e) => {
    if (e.key === "ArrowRight") go(current + 1);
    if (e.key === "ArrowLeft") go(current - 1);
  });
  if (perFrame > 1)
    $("note").textContent = `This run has ${steps.length} steps: the timeline is thinned to ${frameCount} frames of ` +
      `${perFrame} steps each (highlights show all of a frame's steps).`;
  window.g2dTrace = { frameCount, perFrame, steps: steps.length, go, frame: 0, drawn: null, viewer };
  go(frameCount);
  viewer.frame(lo, hi, [1, -2, 1.5]);   // from where the SVG of a 3D grammar looks by default
}
