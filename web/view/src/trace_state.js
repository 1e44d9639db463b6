// What both trace players (trace2d.js, the plan; trace3d.js, in 3D) read of
// a trace (docs/trace.md): the graph at any frame, rebuilt from the deltas,
// and a frame's highlights. Runs of more than MAX_FRAMES steps are grouped
// into frames so that the slider stays usable.
const MAX_FRAMES = 2000;

// Nodes [id, kind, x, y] (and z in 3D), edges [id, kind, source, target],
// faces [id, kind, [corners]] (and [triangles as node ids] in 3D).
const node = ([, kind, x, y, z]) => ({ kind, x, y, z: z || 0 });
const edge = ([, kind, src, dst]) => ({ kind, src, dst });
const face = ([, kind, corners, triangles]) => ({ kind, corners, triangles: triangles || [] });

const emptyState = () => ({ nodes: new Map(), edges: new Map(), faces: new Map() });
const copyState = (s) => ({ nodes: new Map(s.nodes), edges: new Map(s.edges), faces: new Map(s.faces) });

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

export function traceFrames(trace) {
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

  // One frame's highlights: what its steps matched (and kept), deleted,
  // added and moved, as keys "n3", "e7", "f2".
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
    // "matched" means matched and kept. A face deleted and added again kept
    // its id and only gained corners: it is neither.
    for (const key of m.deleted) m.matched.delete(key);
    for (const key of [...m.added]) if (m.deleted.has(key)) m.added.delete(key), m.deleted.delete(key);
    return m;
  }

  // Every place any node ever takes, for a fixed frame: [x0, y0, z0], [x1, y1, z1].
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  const grow = (n) => {
    const { x, y, z } = node(n);
    [x, y, z].forEach((v, i) => ((lo[i] = Math.min(lo[i], v)), (hi[i] = Math.max(hi[i], v))));
  };
  trace.axiom.nodes.forEach(grow);
  steps.forEach((st) => (st.added.nodes.forEach(grow), st.moved.forEach(grow)));
  if (!isFinite(lo[0])) lo.fill(0), hi.fill(1);

  // What the info line says of a frame.
  function describe(frame, m) {
    if (frame === 0) return "The axiom.";
    const first = (frame - 1) * perFrame, last = Math.min(frame * perFrame, steps.length) - 1;
    const st = steps[last];
    const rules = new Set(steps.slice(first, last + 1).map((s) => s.rule));
    const daughters = st.daughters.map((d) => d + 1).join(", ");
    return (first === last ? `Step ${st.step}: production ${st.rule}, daughter ${daughters}` +
                             (st.daughters.length > 1 ? ` (${st.daughters.length} rewrites at once)` : "")
                           : `Steps ${steps[first].step}–${st.step}: ${[...rules].join(", ")}`) +
      `. ${m.matched.size} matched and kept, ${m.deleted.size} deleted, ${m.added.size} added, ${m.moved.size} moved.`;
  }

  return { steps, perFrame, frameCount, stateAt, marks, describe, lo, hi };
}

// The controls both pages have (#first, #prev, #play, #next, #last, #slider,
// #position, #note; arrow keys): `draw(frame)` shows a frame. Returns `go`,
// with `go.dispose()` to let the controls go.
export function playerControls(frames, draw) {
  const { frameCount, perFrame, steps } = frames;
  const $ = (id) => document.getElementById(id);
  let current = 0, timer = null;
  const show = (frame) => {
    current = frame;
    draw(frame);
    $("slider").value = frame;
    $("position").textContent = `${frame} / ${frameCount}`;
  };
  const go = (f) => show(Math.max(0, Math.min(frameCount, f)));
  const slider = $("slider");
  slider.max = frameCount;
  slider.oninput = () => show(Number(slider.value));
  $("first").onclick = () => go(0);
  $("prev").onclick = () => go(current - 1);
  $("next").onclick = () => go(current + 1);
  $("last").onclick = () => go(frameCount);
  const stop = () => (clearInterval(timer), (timer = null), ($("play").textContent = "Play"));
  $("play").onclick = () => {
    if (timer) return stop();
    if (current >= frameCount) go(0);
    $("play").textContent = "Pause";
    timer = setInterval(() => (current >= frameCount ? stop() : go(current + 1)), Math.max(20, 4000 / Math.max(frameCount, 1)));
  };
  // Arrows step unless something that takes text has the focus (the studio's editor).
  const onKey = (e) => {
    const t = e.target;
    if (t instanceof HTMLInputElement && t.type !== "range" || t instanceof HTMLTextAreaElement ||
        t instanceof HTMLElement && t.isContentEditable) return;
    if (e.key === "ArrowRight") go(current + 1);
    if (e.key === "ArrowLeft") go(current - 1);
  };
  document.addEventListener("keydown", onKey);
  $("note").textContent = perFrame > 1 ?
    `This run has ${steps.length} steps: the timeline is thinned to ${frameCount} frames of ` +
      `${perFrame} steps each (highlights show all of a frame's steps).` : "";
  // For a page that plays one trace after another (the studio).
  go.dispose = () => (stop(), document.removeEventListener("keydown", onKey));
  return go;
}
