// Infer mode (Merrell's app, in the studio): an example dropped, picked or
// drawn goes to POST /api/infer, which runs `g2d infer` on it. The pane
// shows the example with its vertices marked by primitive, the primitives
// and rules (small pictures from the server), one generated output
// ("Generate": another seed, through /api/run of the written grammar), and
// opens the written grammar in the editor.
import { createDrawing } from "./infer_drawing.js";

const el = (tag, props = {}, ...children) => {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...children);
  return e;
};

// An SVG the server made, as an element (parsed as XML: no script of it runs under the page's CSP).
function svgNode(text) {
  const svg = new DOMParser().parseFromString(text, "image/svg+xml").documentElement;
  return svg.nodeName === "svg" ? document.importNode(svg, true) : el("span", { textContent: "(no picture)" });
}

const formatOf = (name, text) => (/\.svg$/i.test(name) ? "svg" : /\.json$/i.test(name) ? "json" : /^\s*</.test(text) ? "svg" : "json");
const counted = (n, noun) => `${n} ${noun}${n === 1 ? "" : "s"}`;

export function createInferMode(root, { api, openGrammar }) {
  let asked = 0, grammar = "", seed = 1;
  // Request `mine`'s answer, or null once a newer one of this pane was sent. A 409 from a request
  // that reached the server later (parallel connections reorder them) is asked again, once: the
  // editor's run asks again too, so each asking without end could cancel the other without end.
  async function ask(mine, path, body) {
    for (let tries = 0; ; tries++) {
      const answer = await api("POST", path, body);
      if (mine !== asked) return null;
      if (answer.status !== 409 || tries === 1) return answer;
    }
  }
  const status = el("p", { id: "infer-status", role: "status", textContent: "Drop, pick or draw an example." });

  // Input: a drop zone, a file picker, a drawing, and the grammar's size.
  const file = el("input", { type: "file", id: "infer-file", accept: ".svg,.json" });
  const drop = el("div", { id: "infer-drop", tabIndex: 0, textContent: "Drop an example here: an SVG drawing or the JSON of Merrell's app" });
  Object.assign(drop.style, { border: "2px dashed #999", borderRadius: "6px", padding: "14px", textAlign: "center", color: "#555" });
  const size = el("input", { type: "number", id: "infer-size", min: 1, step: 1, placeholder: "20 × the example" });
  size.style.width = "9em";
  const connected = el("input", { type: "checkbox", id: "infer-connected" });
  const settings = el("div", {}, el("label", { htmlFor: "infer-size", textContent: "Target vertices " }), size, " ",
    connected, el("label", { htmlFor: "infer-connected", textContent: " One connected piece" }));
  const drawing = el("details", { id: "infer-draw" }, el("summary", { textContent: "Draw an example" }));
  createDrawing(drawing, { onUse: (text) => infer(text, "svg", "drawing.svg"), status: (t) => (status.textContent = t) });
  const input = el("section", {},
    drop, el("p", {}, el("label", { htmlFor: "infer-file", textContent: "Example file (.svg, .json) " }), file), drawing, settings);

  // Results.
  const example = el("div", { id: "infer-example" });
  const labels = el("ul", { id: "infer-labels" });
  const primitives = el("ul", { id: "infer-primitives" });
  const rules = el("ol", { id: "infer-rules", start: 0 });
  const generated = el("div", { id: "infer-generated" });
  Object.assign(generated.style, { border: "1px solid #ccc", background: "#fff", minHeight: "4em" });
  const generate = el("button", { type: "button", id: "infer-generate", textContent: "Generate", disabled: true,
    title: "Derive the written grammar again with another seed" });
  const open = el("button", { type: "button", id: "infer-open", textContent: "Open grammar in editor", disabled: true });
  // The example and its output side by side, as Merrell's app has them; then what inference found.
  const figure = (title, ...content) => {
    const f = el("figure", {}, el("h3", { textContent: title }), ...content);
    Object.assign(f.style, { margin: 0, flex: "1 1 260px", minWidth: 0 });
    return f;
  };
  const pair = el("div", {}, figure("Example", example), figure("Generated", el("p", {}, generate, " ", open), generated));
  Object.assign(pair.style, { display: "flex", gap: "16px", flexWrap: "wrap", alignItems: "flex-start" });
  const results = el("section", { id: "infer-results", hidden: true }, pair,
    el("h3", { textContent: "Primitives" }), primitives, el("h3", { textContent: "Rules" }), rules,
    el("h3", { textContent: "Edge labels" }), labels);
  for (const list of [labels, primitives, rules]) Object.assign(list.style, { listStyle: "none", padding: 0, margin: 0 });
  Object.assign(primitives.style, { display: "flex", flexWrap: "wrap", gap: "4px 12px" });
  input.setAttribute("aria-label", "Example");
  root.append(input, status, results);
  Object.assign(root.style, { padding: "8px", display: "block" });

  function showGenerated(svgText, note) {
    const svg = svgNode(svgText);
    Object.assign(svg.style, { width: "100%", height: "auto", maxHeight: "60vh", display: "block" });
    generated.replaceChildren(svg);
    generated.title = note;
  }

  function show(data) {
    grammar = data.grammar;
    seed = data.seed;
    const ex = svgNode(data.example_svg);
    ex.style.maxWidth = "100%";
    example.replaceChildren(ex);
    labels.replaceChildren(...data.labels.map((l) => {
      const swatch = el("span", { textContent: "━━ " });
      swatch.style.color = l.color;
      return el("li", {}, swatch, `${l.id}: ${l.brush} at ${+l.direction.toFixed(1)}°, left ${l.left}, right ${l.right}, ` +
        `length ${+l.min_length.toFixed(3)} to ${+l.max_length.toFixed(3)}, ${l.count} in the example`);
    }));
    primitives.replaceChildren(...data.primitives.map((p) => {
      const star = p.halves.map((h) => `${h.label} ${h.out ? "out" : "in"} ${+h.direction.toFixed(1)}°`).join(", ");
      const item = el("li", { className: "primitive" }, svgNode(p.svg), el("span", { textContent: ` ${p.id}: ${star} (${p.count} in the example)` }));
      Object.assign(item.style, { display: "flex", alignItems: "center", gap: "6px", flex: "0 1 22em" });
      return item;
    }));
    rules.replaceChildren(...data.rules.map((r) => {
      const right = r.starter ? "nothing" : r.right.join(" | ");
      const item = el("li", { className: "rule" },
        el("div", { textContent: `${r.index}: ${r.left} ↔ ${right}${r.restructures ? " (restructures)" : ""}${r.starter ? " (starter)" : ""}` }),
        el("div", {}, svgNode(r.left_svg), el("span", { textContent: " ↔ " }), r.right_svg ? svgNode(r.right_svg) : el("span", { textContent: "nothing" })));
      item.style.margin = "6px 0";
      item.lastChild.style.cssText = "display: flex; align-items: center; gap: 6px; flex-wrap: wrap";
      return item;
    }));
    if (data.generated_svg) showGenerated(data.generated_svg, `seed ${data.seed}`);
    else generated.replaceChildren(el("p", { className: "error", textContent: "No output: " + data.generate_error }));
    generate.disabled = open.disabled = false;
    results.hidden = false;
    const c = data.counts;
    status.textContent = `${data.name}: ${counted(c.labels, "edge label")}, ${counted(c.primitives, "primitive")}, ` +
      `${counted(c.rules, "rule")} and ${counted(c.starters, "starter rule")} in ${data.ms.toFixed(0)} ms; seed ${data.seed}` +
      (data.warning ? `. Note: ${data.warning}` : "");
  }

  async function infer(text, format, name) {
    const mine = ++asked;
    status.textContent = `Inferring a grammar from ${name}…`;
    status.className = "";
    const body = { example: text, format, name, seed: 1, connected: connected.checked };
    if (size.value) body.size = Number(size.value);
    const answer = await ask(mine, "/api/infer", body);
    if (!answer) return;   // a newer request answers
    const { status: code, data } = answer;
    if (code === 409) return (status.textContent = "Cancelled by a run of the editor: try again");
    if (code === 200 && data.status === "ok") return show(data);
    status.textContent = data && data.message ? "The example was refused: " + data.message : `The inference failed (${code})`;
    status.className = "error";
  }

  async function readFile(f) {
    if (!f) return;
    const text = await f.text();
    infer(text, formatOf(f.name, text), f.name);
  }
  file.addEventListener("change", () => readFile(file.files[0]));
  drop.addEventListener("dragover", (e) => (e.preventDefault(), (drop.style.borderColor = "#36c")));
  drop.addEventListener("dragleave", () => (drop.style.borderColor = "#999"));
  drop.addEventListener("drop", (e) => {
    e.preventDefault();
    drop.style.borderColor = "#999";
    readFile(e.dataTransfer.files[0]);
  });
  drop.addEventListener("keydown", (e) => (e.key === "Enter" || e.key === " ") && (e.preventDefault(), file.click()));

  generate.addEventListener("click", async () => {
    const mine = ++asked;
    seed += 1;
    status.textContent = `Generating with seed ${seed}…`;
    const answer = await ask(mine, "/api/run", { text: grammar, seed });
    if (!answer) return;
    const { status: code, data } = answer;
    if (code === 200 && data.svg) {
      showGenerated(data.svg, `seed ${seed}`);
      status.textContent = `Generated with seed ${seed}: ${counted(data.elements.nodes, "node")}, ${data.ms.toFixed(0)} ms`;
    } else if (code === 409) status.textContent = "Cancelled by a run of the editor: press Generate again";
    else status.textContent = `No output for seed ${seed}: ${data && data.message ? data.message : code}`;
  });
  open.addEventListener("click", () => openGrammar(grammar));

  return { infer };
}
