// The page of `g2d studio` (compiler/studio/): the grammar in an editor,
// re-derived on every edit and drawn at once; the parameters panel; the
// derivation player; the seeds sheet; infer mode; export buttons. All
// through the studio's JSON API: a newer run cancels the older one on the
// server, and an answer the page no longer wants is dropped. An error keeps
// the last good picture. Saves send the version the text was loaded at; a
// change on disk reloads a text the user has not edited.
import { api } from "./api.js";
import { createEditor } from "./editor.js";
import { createExports } from "./exports.js";
import { createParamsPanel } from "./params_panel.js";
import { createPicture } from "./picture.js";
import { createPlayer } from "./player.js";
import { createSeedsSheet } from "./seeds_sheet.js";
import { createTabs } from "./tabs.js";
import { createInferMode } from "./infer_mode.js";

const $ = (id) => document.getElementById(id);
const statusLine = $("status"), list = $("diagnostics");
let path = "", version = "none", dirty = false, asked = 0, editedAt = null;
// For tests and the benchmark: what the page has drawn, and when.
const studio = (window.g2dStudio = { runs: 0, draws: 0, last: null, errors: 0 });

const say = (text) => (statusLine.textContent = text);
const counted = (n, noun) => `${n} ${noun}${n === 1 ? "" : "s"}`;

const complete = async (text, line, character) => {
  const { status: code, data } = await api("POST", "/api/complete", { text, line, character });
  return code === 200 ? data.items : null;
};
const editor = createEditor($("editor"), { onEdit: edited, onSave: () => save(), complete });
const params = createParamsPanel($("params"), () => run());
const picture = createPicture({ flat: $("flat"), solid: $("solid"), panel: $("view-panel"), note: $("picture-note") });
const player = createPlayer({ stage: $("stage"), solid: $("player-solid"), panel: $("player-panel"), info: $("info") });
const request = () => ({ text: editor.text(), ...params.request() });
// As `g2d run --obj NAME.obj` names them, so that the OBJ finds its MTL.
const stem = () => (path.split("/").pop() || "untitled.g2d").replace(/\.g2d$/, "");
const sheet = createSeedsSheet($("seeds-pane"), { api, request, status: say, takeSeed: (seed) => (tabs.open("picture"), params.setSeed(seed)) });
createExports($("exports"), { api, request, stem, status: say });
const tabs = createTabs({
  picture: () => {},
  player: () => play(),
  seeds: () => sheet.fill(),
  infer: (first) => first && createInferMode($("infer-pane"), { api, openGrammar }),
});

// A diagnostic of this text is shown at its line; one of an imported file only in the list.
const inThisText = (d) => !d.file || d.file === path || (!path && d.file.endsWith("untitled.g2d"));

function showDiagnostics(diagnostics, extra) {
  editor.showDiagnostics(diagnostics, inThisText);
  list.replaceChildren();
  const item = (cls, text) => list.append(Object.assign(document.createElement("li"), { className: cls, textContent: text }));
  for (const d of diagnostics || [])
    item(d.severity, `${inThisText(d) ? "" : (d.file || "").split("/").pop() + ":"}${d.line}:${d.column}: ${d.severity}: ${d.message}`);
  if (extra) item("error", extra);
}

// The newest good answer not drawn yet, and the id of the newest answer of any kind.
let waiting = null, answered = 0;

async function run() {
  const mine = ++asked;
  studio.runs++;
  const { status: code, data } = await api("POST", "/api/run", request());
  if (mine !== asked) return;   // a newer run answers
  // Cancelled by an older request that reached the server later (requests travel on parallel
  // connections): this is still the run the page wants, so it asks again.
  if (code === 409) return run();
  answered = mine;
  if (data.params) params.draw(data.params);
  if (data.status === "ok") {
    // Drawn in the next animation frame, the newest answer only: answers that come faster than
    // frames (a slow GL behind them) are not all drawn, each after the other.
    if (waiting === null) requestAnimationFrame(() => draw(waiting));
    waiting = { data, mine };
  } else {
    // The last good picture stays.
    studio.errors++;
    const where = data.location ? `${data.location.line}:${data.location.column}: ` : "";
    showDiagnostics(data.diagnostics, data.message ? where + data.message : "");
    say(data.status === "invalid" ? "The grammar has errors: the picture is the last good one" : "The run failed: the picture is the last good one");
  }
}

function draw({ data, mine }) {
  waiting = null;
  // An answer of a broken text that came after this one keeps its diagnostics and status.
  const newest = mine === answered;
  try {
    picture.show(data);
  } catch (e) {
    if (newest) showDiagnostics(data.diagnostics, "The picture could not be drawn: " + e.message);
    return;
  }
  studio.draws++;
  const e = data.elements;
  const last = (studio.last = { editedAt, drawnAt: performance.now(), paintedAt: null, serverMs: data.ms, space: data.space,
                                elements: e, steps: data.steps });
  // This animation frame shows the picture: it has been painted once the next task runs
  // (`onPaint`, the benchmark's, then waits for the GL work behind it).
  setTimeout(() => ((last.paintedAt = performance.now()), studio.onPaint && studio.onPaint(last)));
  editedAt = null;
  if (!newest) return;
  showDiagnostics(data.diagnostics, data.warning);
  say([counted(data.steps, "step"), counted(e.nodes, "node"), counted(e.edges, "edge"), counted(e.faces, "face"),
       `${data.ms.toFixed(1)} ms`].join(", "));
  if (tabs.current() === "player") play();
  else if (tabs.current() === "seeds") sheet.fill();
}

async function play() {
  const mine = ++asked;
  say("Recording the derivation…");
  const { status: code, data } = await api("POST", "/api/run", { ...request(), trace: true });
  if (mine !== asked) return;
  if (code === 409) return play();   // as in run()
  if (data.status !== "ok") return say("The grammar has errors: the player shows the last good run");
  player.play(data);
  say(`${counted(data.steps, "step")}: step through with the buttons or the arrow keys`);
}

// The inferred grammar replaces the text (unsaved: Save would write it over the file, so unsaved
// edits are not thrown away without asking).
function openGrammar(text) {
  if (dirty && !confirm(`Replace your unsaved edits of ${$("file").textContent} with the inferred grammar?`)) return;
  editor.setText(text);
  tabs.open("picture");
  edited();
}

function edited() {
  dirty = true;
  if (editedAt === null) editedAt = performance.now();
  run();
}

async function load() {
  const { data } = await api("GET", "/api/file");
  path = data.path || "";
  $("file").textContent = path ? path.split("/").pop() : "untitled";
  $("file").title = path;
  document.title = `${$("file").textContent} — g2d studio`;
  editor.setText(data.text);
  version = data.version;
  dirty = false;
  await run();
}

// The file changed on disk under unsaved edits: the user reloads it or keeps the edits.
let diskVersion = null;
function conflict(onDisk) {
  diskVersion = onDisk;
  $("conflict").hidden = onDisk === null;
}

// `over`: written over the file as it is on disk now (the user chose to keep the edits).
async function save(over = false) {
  const { status: code, data } = await api("PUT", "/api/file", { text: editor.text(), version: over ? diskVersion : version });
  if (code === 200) {
    version = data.version;
    dirty = false;
    conflict(null);
    say("Saved");
  } else if (code === 409) {
    conflict(data.version);
    say("Not saved: " + data.message);
  } else {
    say(data.message);
  }
}

$("save").addEventListener("click", () => save());
$("reload-file").addEventListener("click", () => (conflict(null), load()));
$("overwrite-file").addEventListener("click", () => save(true));
const events = new EventSource("/api/events");
events.addEventListener("file", (e) => {
  const changed = JSON.parse(e.data).version;
  if (changed === version) return;   // our own save
  if (dirty) conflict(changed);
  else load();
});
Object.assign(studio, {
  text: () => editor.text(),
  marks: () => editor.marks(),
  select: (text) => editor.select(text),
  camera: () => picture.viewer() && picture.viewer().camera(),
  programs: () => picture.viewer() && picture.viewer().programs(),
});
load();
