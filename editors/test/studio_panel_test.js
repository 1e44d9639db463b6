#!/usr/bin/env node
// "g2d: Open Studio" without VS Code: editors/vscode/studio_panel.js starts
// the real `g2d studio` on a copy of an example and reads its URL, the page
// answers through it, the webview's HTML frames exactly that origin, and
// stopping ends the server; a server that exits early, prints something
// else or nothing, or cannot start is an error that carries its stderr.
// Then extension.js against a stand-in `vscode` module: the command saves
// the editor, opens one panel per file (again: reveals it), closing the
// panel and deactivating stop the server. And package.json contributes it.
// usage: node editors/test/studio_panel_test.js G2D SOURCE_DIR
"use strict";
const fs = require("fs");
const os = require("os");
const path = require("path");
const Module = require("module");

const [g2d, src] = process.argv.slice(2).map((p) => path.resolve(p));
const vscodeDir = path.join(src, "editors/vscode");
// Every process the module starts, so that a failing check leaves no server behind.
const childProcess = require("child_process");
const spawned = [];
const originalSpawn = childProcess.spawn;
childProcess.spawn = (...args) => { const child = originalSpawn(...args); spawned.push(child); return child; };
process.on("exit", () => spawned.forEach((child) => child.exitCode === null && child.signalCode === null && child.kill("SIGKILL")));
const { startStudio, studioHtml, webviewOptions, studioOrigin } = require(path.join(vscodeDir, "studio_panel.js"));

let failed = 0, passed = 0;
function check(ok, what) {
  if (ok) passed++;
  else { failed++; console.log("FAIL: " + what); }
}

const work = fs.mkdtempSync(path.join(os.tmpdir(), "g2d-studio-panel-"));
const grammar = path.join(work, "sierpinski.g2d");
fs.copyFileSync(path.join(src, "examples/sierpinski.g2d"), grammar);

const sleep = (ms) => new Promise((done) => setTimeout(done, ms));
const alive = (pid) => { try { process.kill(pid, 0); return true; } catch { return false; } };
async function answers(url) {
  try { return (await fetch(url)).status === 200; } catch { return false; }
}
// A stand-in server: a shell script, so that each way of failing can be tried.
function script(name, body) {
  const file = path.join(work, name);
  fs.writeFileSync(file, `#!/bin/sh\necho $$ > "${file}.pid"\n${body}\n`, { mode: 0o755 });
  return file;
}
async function rejection(promise) {
  try { await promise; return null; } catch (err) { return err.message; }
}

async function moduleChecks() {
  const studio = await startStudio(g2d, grammar);
  check(/^http:\/\/127\.0\.0\.1:\d+\/$/.test(studio.url) && studio.url === `http://127.0.0.1:${studio.port}/`,
        `the URL line: ${studio.url}`);
  // The webview's iframe sends Host 127.0.0.1:PORT (its src, the port mapped to itself), as fetch does.
  const res = await fetch(studio.url);
  const page = await res.text();
  check(res.status === 200 && page.includes('<script src="/studio.js">'), `GET / through the URL: ${res.status}`);
  const ancestors = (res.headers.get("content-security-policy") || "").split(";").map((d) => d.trim())
    .find((d) => d.startsWith("frame-ancestors ")) || "";
  check(["vscode-webview:", "vscode-file:"].every((s) => ancestors.split(" ").includes(s)),
        `the page may be framed by a VS Code webview: ${ancestors}`);
  const file = await (await fetch(studio.url + "api/file")).json();
  check(file.path === grammar && file.text === fs.readFileSync(grammar, "utf8"), `the studio edits the file: ${file.path}`);

  const html = studioHtml(studio.url, "Studio: sierpinski.g2d");
  const policy = /<meta http-equiv="Content-Security-Policy" content="([^"]*)">/.exec(html);
  check(policy && policy[1] === `default-src 'none'; frame-src http://127.0.0.1:${studio.port}; style-src 'unsafe-inline'`,
        `the webview's policy frames exactly the studio: ${policy && policy[1]}`);
  check(studioOrigin(studio.url) === `http://127.0.0.1:${studio.port}`, "the studio's origin");
  const frames = [...html.matchAll(/<iframe src="([^"]*)"/g)].map((m) => m[1]);
  check(frames.length === 1 && frames[0] === studio.url && !/<script/i.test(html), `one iframe of the URL, no script: ${frames}`);
  check(/iframe[^{]*\{[^}]*width: 100%; height: 100%/.test(html), "the iframe fills the panel");
  check(studioHtml("http://127.0.0.1:1/", 'a"<b').includes("a&quot;&lt;b"), "the title is escaped");
  const options = webviewOptions(studio.port);
  check(options.enableScripts === true && JSON.stringify(options.portMapping) ===
        JSON.stringify([{ webviewPort: studio.port, extensionHostPort: studio.port }]), `webview options: ${JSON.stringify(options)}`);

  const pid = studio.process.pid;
  await studio.stop();
  check(!alive(pid) && !(await answers(studio.url)), "stop() ends the server");
  await studio.stop();   // twice: nothing more to do

  // Failures, each with what the server said.
  const early = await rejection(startStudio(g2d, work));
  check(early && early.includes("ended before printing its URL") && early.includes("is not a file"), `an early exit: ${early}`);
  const silent = script("silent.sh", "echo 'still starting' >&2\nexec sleep 30");
  const slow = await rejection(startStudio(silent, grammar, { timeoutMs: 500 }));
  check(slow && slow.includes("printed no URL within 0.5 s") && slow.includes("still starting"), `no URL in time: ${slow}`);
  const other = script("other.sh", "echo hello\nexec sleep 30");
  const wrong = await rejection(startStudio(other, grammar));
  check(wrong && wrong.includes("printed `hello` instead of its URL"), `another first line: ${wrong}`);
  await sleep(300);
  for (const s of [silent, other]) {
    const spid = Number(fs.readFileSync(s + ".pid", "utf8"));
    check(!alive(spid), `${path.basename(s)}: the process is stopped after the error`);
  }
  const missing = await rejection(startStudio(path.join(work, "no-such-g2d"), grammar));
  check(missing && missing.includes("cannot start") && missing.includes("ENOENT"), `no executable: ${missing}`);
}

// extension.js with a stand-in vscode module.
async function extensionChecks() {
  const errors = [], panels = [], commands = {};
  let executable = g2d;
  class Uri { constructor(fsPath, scheme = "file") { this.fsPath = fsPath; this.scheme = scheme; } }
  const document = { languageId: "g2d", isUntitled: false, isDirty: true, uri: new Uri(grammar), saves: 0,
                     save() { this.saves++; this.isDirty = false; return Promise.resolve(true); } };
  const fakeVscode = {
    Uri,
    ViewColumn: { Beside: -2 },
    workspace: { getConfiguration: () => ({ get: () => executable }), openTextDocument: async () => document },
    window: {
      activeTextEditor: { document },
      showErrorMessage: (m) => errors.push(m),
      createWebviewPanel: (viewType, title, column, options) => {
        const listeners = [];
        const panel = { viewType, title, column, options, reveals: 0, disposed: false, webview: { html: "" },
                        reveal() { this.reveals++; },
                        onDidDispose(f) { listeners.push(f); },
                        dispose() { if (!this.disposed) { this.disposed = true; listeners.forEach((f) => f()); } } };
        panels.push(panel);
        return panel;
      },
    },
    commands: { registerCommand: (id, f) => { commands[id] = f; return { dispose() {} }; } },
  };
  const originalLoad = Module._load;
  Module._load = function (request) {
    if (request === "vscode") return fakeVscode;
    if (request === "vscode-languageclient/node") {
      return { TransportKind: { stdio: 0 },
               LanguageClient: class { start() { return Promise.resolve(); } stop() { return Promise.resolve(); } } };
    }
    return originalLoad.apply(this, arguments);
  };
  const extension = require(path.join(vscodeDir, "extension.js"));
  Module._load = originalLoad;
  extension.activate({ subscriptions: [] });
  const open = commands["g2d.openStudio"];
  check(typeof open === "function", "activation registers g2d.openStudio");
  if (!open) return;

  await open();
  check(document.saves === 1, "the dirty editor is saved before the studio starts");
  check(panels.length === 1 && errors.length === 0, `one panel: ${panels.length}, errors: ${errors}`);
  const panel = panels[0];
  const port = panel && panel.options.portMapping[0].webviewPort;
  const url = `http://127.0.0.1:${port}/`;
  check(panel.viewType === "g2d.studio" && panel.title === "Studio: sierpinski.g2d" &&
        JSON.stringify(panel.options) === JSON.stringify(webviewOptions(port)) &&
        panel.webview.html === studioHtml(url, panel.title), `the panel: ${JSON.stringify(panel.options)}`);
  check(await answers(url), "the studio answers at the panel's URL");
  await Promise.all([open(), open(new Uri(grammar))]);   // the title bar passes the file
  check(panels.length === 1 && panel.reveals === 2 && document.saves === 1, `again: revealed (${panel.reveals}), not restarted`);

  panel.dispose();
  let stopped = false;
  for (let i = 0; i < 50 && !stopped; i++) { await sleep(100); stopped = !(await answers(url)); }
  check(stopped, "closing the panel stops the studio");

  await open();
  check(panels.length === 2 && await answers(`http://127.0.0.1:${panels[1].options.portMapping[0].webviewPort}/`),
        "after closing, the command starts a new studio");
  const second = `http://127.0.0.1:${panels[1].options.portMapping[0].webviewPort}/`;
  await extension.deactivate();
  check(panels[1].disposed && !(await answers(second)), "deactivate stops every studio");

  document.isUntitled = true;
  await open();
  document.isUntitled = false;
  check(panels.length === 2 && errors.length === 1 && errors[0].includes("save the grammar"), `an untitled editor: ${errors}`);
  executable = path.join(work, "no-such-g2d");
  await open();
  check(panels.length === 2 && errors.length === 2 && errors[1].includes("cannot start"), `no executable: ${errors[1]}`);
}

function manifestChecks() {
  const manifest = JSON.parse(fs.readFileSync(path.join(vscodeDir, "package.json"), "utf8"));
  const command = (manifest.contributes.commands || []).find((c) => c.command === "g2d.openStudio");
  check(command && command.title === "g2d: Open Studio", `the command's title: ${JSON.stringify(command)}`);
  const menus = manifest.contributes.menus || {};
  const palette = (menus.commandPalette || []).find((m) => m.command === "g2d.openStudio");
  const title = (menus["editor/title"] || []).find((m) => m.command === "g2d.openStudio");
  check(palette && palette.when === "editorLangId == g2d", `in the command palette for g2d files: ${JSON.stringify(palette)}`);
  check(title && title.when === "resourceLangId == g2d", `in the editor title bar of g2d files: ${JSON.stringify(title)}`);
}

async function main() {
  await moduleChecks();
  await extensionChecks();
  manifestChecks();
  fs.rmSync(work, { recursive: true, force: true });
  console.log(`${passed} passed, ${failed} failed`);
  process.exit(failed ? 1 : 0);
}

main().catch((e) => { console.log("FAIL: " + (e.stack || e)); process.exit(1); });
