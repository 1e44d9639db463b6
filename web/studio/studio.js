// The first studio page: a text area, the picture and the diagnostics, on
// the studio's JSON API (compiler/studio/studio_routes.hpp). Each edit
// re-derives after a short pause; a newer run cancels the older one on the
// server; an error keeps the last good picture. Saving sends the version
// the text was loaded at, and a change on disk reloads an unedited text.
"use strict";
(() => {
  const $ = (id) => document.getElementById(id);
  const editor = $("editor"), picture = $("picture"), list = $("diagnostics"), status = $("status");
  let version = "none", dirty = false, timer = 0, asked = 0;

  async function api(method, path, body) {
    const init = { method, headers: {} };
    if (body !== undefined) {
      init.headers["Content-Type"] = "application/json";
      init.body = JSON.stringify(body);
    }
    const res = await fetch(path, init);
    return { status: res.status, data: await res.json() };
  }

  function showDiagnostics(diagnostics, extra) {
    list.replaceChildren();
    for (const d of diagnostics || []) {
      const li = document.createElement("li");
      li.className = d.severity;
      li.textContent = `${d.line}:${d.column}: ${d.severity}: ${d.message}`;
      list.append(li);
    }
    if (extra) {
      const li = document.createElement("li");
      li.className = "error";
      li.textContent = extra;
      list.append(li);
    }
  }

  function showPicture(svgText) {
    const doc = new DOMParser().parseFromString(svgText, "image/svg+xml");
    const svg = doc.documentElement;
    if (svg.nodeName !== "svg") return;
    picture.replaceChildren(document.importNode(svg, true));
  }

  async function run() {
    const mine = ++asked;
    status.textContent = "Deriving…";
    const { data } = await api("POST", "/api/run", { text: editor.value, seed: 1 });
    if (mine !== asked || data.status === "cancelled") return;   // a newer run answers
    if (data.status === "ok") {
      showPicture(data.svg);
      showDiagnostics(data.diagnostics, data.warning);
      const e = data.elements;
      const counted = (n, noun) => `${n} ${noun}${n === 1 ? "" : "s"}`;
      status.textContent = [counted(data.steps, "step"), counted(e.nodes, "node"), counted(e.edges, "edge"),
                            counted(e.faces, "face"), `${data.ms.toFixed(1)} ms`].join(", ");
    } else {
      // The last good picture stays.
      const where = data.location ? `${data.location.line}:${data.location.column}: ` : "";
      showDiagnostics(data.diagnostics, data.message ? where + data.message : "");
      status.textContent = data.status === "invalid" ? "The grammar has errors" : "The run failed";
    }
  }

  function edited() {
    dirty = true;
    clearTimeout(timer);
    timer = setTimeout(run, 150);
  }

  async function load() {
    const { data } = await api("GET", "/api/file");
    $("file").textContent = data.path || "untitled";
    editor.value = data.text;
    version = data.version;
    dirty = false;
    await run();
  }

  async function save() {
    const { status: code, data } = await api("PUT", "/api/file", { text: editor.value, version });
    if (code === 200) {
      version = data.version;
      dirty = false;
      status.textContent = "Saved";
    } else {
      status.textContent = data.message;
    }
  }

  editor.addEventListener("input", edited);
  $("save").addEventListener("click", save);
  const events = new EventSource("/api/events");
  events.addEventListener("file", (e) => {
    const changed = JSON.parse(e.data).version;
    if (changed === version) return;   // our own save
    if (dirty) status.textContent = "The file changed on disk; saving will say so";
    else load();
  });
  load();
})();
