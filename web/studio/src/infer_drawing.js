// A small drawing surface for infer mode: click points on a grid to draw
// polylines; close one (click its first point, or "Close shape") to make a
// polygon filled with the chosen area colour. `svgText()` writes the drawing
// as the SVG `g2d infer` reads (docs/infer.md, "Examples drawn as SVG"):
// stroke colour = edge label, fill colour = area label, 40 units a cell.
const SVG_NS = "http://www.w3.org/2000/svg";
const CELL = 40, SNAP = 20, COLS = 12, ROWS = 8;
const STROKES = [["#000000", "black"], ["#e15759", "red"], ["#4e79a7", "blue"], ["#59a14f", "green"], ["#8b4513", "brown"]];
const FILLS = [["none", "no area"], ["#d2b48c", "tan"], ["#b22222", "firebrick"], ["#87ceeb", "sky blue"], ["#90ee90", "light green"]];

const el = (tag, props = {}, ...children) => {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...children);
  return e;
};
const svgEl = (tag, attrs) => {
  const e = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  return e;
};
const pointsText = (points) => points.map(([x, y]) => `${x},${y}`).join(" ");

function select(id, label, options) {
  const s = el("select", { id });
  for (const [value, text] of options) s.append(el("option", { value, textContent: text }));
  return [el("label", { htmlFor: id, textContent: label }), s];
}

// `onUse(svgText)` is called by "Use drawing".
export function createDrawing(root, { onUse, status }) {
  const shapes = [];   // {points: [[x, y]…], closed, stroke, fill}
  let current = [];
  const [strokeLabel, stroke] = select("infer-stroke", "Line colour", STROKES);
  const [fillLabel, fill] = select("infer-fill", "Area colour (closed shapes)", FILLS);
  fill.value = "#d2b48c";
  const button = (id, text, title, action) => {
    const b = el("button", { type: "button", id, textContent: text, title });
    b.addEventListener("click", action);
    return b;
  };
  const canvas = svgEl("svg", { id: "infer-canvas", viewBox: `0 0 ${COLS * CELL} ${ROWS * CELL}`, role: "img",
    "aria-label": "Drawing grid: click to add points" });
  Object.assign(canvas.style, { width: "100%", maxWidth: `${COLS * CELL}px`, background: "#fff", border: "1px solid #bbb",
    cursor: "crosshair", display: "block", touchAction: "none" });
  const grid = svgEl("g", { stroke: "#e4e4e4", "stroke-width": "1" });
  for (let x = 0; x <= COLS * CELL; x += CELL) grid.append(svgEl("line", { x1: x, y1: 0, x2: x, y2: ROWS * CELL }));
  for (let y = 0; y <= ROWS * CELL; y += CELL) grid.append(svgEl("line", { x1: 0, y1: y, x2: COLS * CELL, y2: y }));
  const drawn = svgEl("g", { "stroke-width": "3", "stroke-linejoin": "round" });
  canvas.append(grid, drawn);

  function redraw() {
    drawn.replaceChildren();
    for (const s of shapes)
      drawn.append(svgEl(s.closed ? "polygon" : "polyline", { points: pointsText(s.points), stroke: s.stroke,
        fill: s.closed ? (s.fill === "none" ? "none" : s.fill) : "none", "fill-opacity": "0.6" }));
    if (current.length) {
      drawn.append(svgEl("polyline", { points: pointsText(current), stroke: stroke.value, fill: "none", "stroke-dasharray": "6 4" }));
      const [x, y] = current[0];
      drawn.append(svgEl("circle", { cx: x, cy: y, r: 6, fill: "#fff", stroke: stroke.value, "stroke-width": "2" }));
    }
  }
  function finish(closed) {
    if (current.length >= (closed ? 3 : 2)) shapes.push({ points: current, closed, stroke: stroke.value, fill: fill.value });
    current = [];
    redraw();
  }
  // A point in grid units from a click (snapped to half cells).
  function gridPoint(event) {
    const box = canvas.getBoundingClientRect();
    const snap = (v, size, most) => Math.max(0, Math.min(most, Math.round((v / size) * most / SNAP) * SNAP));
    return [snap(event.clientX - box.left, box.width, COLS * CELL), snap(event.clientY - box.top, box.height, ROWS * CELL)];
  }
  canvas.addEventListener("click", (event) => {
    const p = gridPoint(event);
    const last = current[current.length - 1];
    if (last && last[0] === p[0] && last[1] === p[1]) return finish(false);   // the same point twice: the line ends
    if (current.length >= 3 && current[0][0] === p[0] && current[0][1] === p[1]) return finish(true);
    current.push(p);
    redraw();
  });

  const toolbar = el("div", {}, strokeLabel, stroke, fillLabel, fill,
    button("infer-end-line", "End line", "End the line being drawn (or click its last point again)", () => finish(false)),
    button("infer-close-shape", "Close shape", "Close the line into a filled shape (or click its first point)", () => finish(true)),
    button("infer-undo", "Undo", "Take back the last point or shape", () => {
      if (current.length) current.pop();
      else shapes.pop();
      redraw();
    }),
    button("infer-clear", "Clear", "Clear the drawing", () => ((shapes.length = 0), (current = []), redraw())),
    button("infer-use-drawing", "Use drawing", "Infer a grammar from this drawing", () => {
      finish(false);
      if (!shapes.length) return status("Draw a line first: click points on the grid");
      onUse(svgText());
    }));
  Object.assign(toolbar.style, { display: "flex", flexWrap: "wrap", gap: "6px", alignItems: "center", margin: "4px 0" });
  root.append(toolbar, canvas);

  function svgText() {
    const lines = shapes.map((s) =>
      `  <${s.closed ? "polygon" : "polyline"} points="${pointsText(s.points)}" stroke="${s.stroke}" fill="${s.closed ? s.fill : "none"}"/>`);
    return `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ${COLS * CELL} ${ROWS * CELL}">\n  <title>Drawing</title>\n` +
      lines.join("\n") + "\n</svg>\n";
  }
  return { svgText, clear: () => ((shapes.length = 0), (current = []), redraw()) };
}
