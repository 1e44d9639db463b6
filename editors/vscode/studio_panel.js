// The parts of "g2d: Open Studio" that need no VS Code: start `g2d studio`
// and read its URL, the webview's HTML and options, and one studio per file
// (editors/test/studio_panel_test.js runs them against the real server).
// extension.js injects the VS Code parts: the panel and the messages.
"use strict";
const { spawn } = require("child_process");
const path = require("path");

// The server prints exactly this as its first line (compiler/studio/studio.cpp).
const URL_LINE = /^http:\/\/127\.0\.0\.1:(\d+)\/$/;

// How long the server has to print its URL, and to end after SIGTERM.
const START_TIMEOUT_MS = 10000;
const STOP_GRACE_MS = 3000;

// Starts `COMMAND studio FILE --port 0` in the file's folder. Resolves to
// {url, port, process, stop()} once the URL line is read; rejects (with the
// server's stderr in the message) if it exits first, prints something else,
// or prints nothing within `timeoutMs`; the process is stopped then.
function startStudio(command, file, { timeoutMs = START_TIMEOUT_MS } = {}) {
  return new Promise((resolve, reject) => {
    const child = spawn(command, ["studio", file, "--port", "0"],
                        { cwd: path.dirname(file), stdio: ["ignore", "pipe", "pipe"] });
    let stdout = "", stderr = "", settled = false;
    const fail = (why) => {
      if (settled) return;
      settled = true;
      clearTimeout(timer);
      stopProcess(child);
      const said = stderr.trim();
      reject(new Error(`\`${command} studio\` ${why}${said ? `: ${said}` : ""}`));
    };
    const timer = setTimeout(() => fail(`printed no URL within ${timeoutMs / 1000} s`), timeoutMs);
    child.stderr.setEncoding("utf8");
    child.stderr.on("data", (chunk) => { stderr += chunk; });
    child.stdout.setEncoding("utf8");
    child.stdout.on("data", (chunk) => {
      if (settled) return;
      stdout += chunk;
      const end = stdout.indexOf("\n");
      if (end < 0) return;
      const line = stdout.slice(0, end).trim();
      const match = URL_LINE.exec(line);
      if (!match) return fail(`printed \`${line}\` instead of its URL`);
      settled = true;
      clearTimeout(timer);
      child.stdout.resume();   // later output must not fill the pipe
      resolve({ url: line, port: Number(match[1]), process: child, stop: () => stopProcess(child) });
    });
    child.on("error", (err) => fail(`cannot start (${err.message})`));
    // 'close' (not 'exit'): stderr has been read whole by then.
    child.on("close", (code, signal) => fail(`ended before printing its URL (${signal || `exit code ${code}`})`));
  });
}

// SIGTERM (the server shuts down in order), then SIGKILL if it is still
// there after STOP_GRACE_MS. Resolves once the process has ended.
function stopProcess(child) {
  if (child.pid === undefined || child.exitCode !== null || child.signalCode !== null) return Promise.resolve();
  return new Promise((resolve) => {
    const kill = setTimeout(() => child.kill("SIGKILL"), STOP_GRACE_MS);
    child.once("exit", () => { clearTimeout(kill); resolve(); });
    child.kill("SIGTERM");
  });
}

// The studio's origin, the only one the webview may frame: `http://127.0.0.1:PORT`.
function studioOrigin(url) {
  return new URL(url).origin;
}

// Webview options: scripts on (the iframe inherits the webview's sandbox);
// the page kept while its tab is hidden (else the studio would reload and
// lose its unsaved text); and the studio's port mapped to itself, as VS Code
// asks of any webview that loads localhost content (through a tunnel when
// the extension runs remotely).
function webviewOptions(port) {
  return { enableScripts: true, retainContextWhenHidden: true, portMapping: [{ webviewPort: port, extensionHostPort: port }] };
}

const escapeAttr = (s) => s.replace(/&/g, "&amp;").replace(/"/g, "&quot;").replace(/</g, "&lt;");

// The webview's page: no script of its own, one full-size iframe of the
// studio, and a policy that frames exactly the studio's origin.
function studioHtml(url, title) {
  const policy = `default-src 'none'; frame-src ${studioOrigin(url)}; style-src 'unsafe-inline'`;
  return `<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="${escapeAttr(policy)}">
<title>${escapeAttr(title)}</title>
<style>html, body, iframe { margin: 0; padding: 0; border: 0; width: 100%; height: 100%; overflow: hidden; display: block; }</style>
</head>
<body><iframe src="${escapeAttr(url)}" title="${escapeAttr(title)}"></iframe></body>
</html>
`;
}

// One studio per file. `start(file)` resolves to a started studio;
// `createPanel(file, studio)` returns a panel with reveal(), dispose() and
// onDidDispose(callback). Closing the panel stops the studio.
class StudioPanels {
  constructor({ start, createPanel }) {
    this.start = start;
    this.createPanel = createPanel;
    this.open_ = new Map();   // file -> Promise<{panel, studio}>
  }

  // Reveals the file's studio, starting it first if there is none.
  open(file) {
    const existing = this.open_.get(file);
    if (existing) return existing.then((entry) => { entry.panel.reveal(); return entry; });
    const opening = this.start(file).then((studio) => {
      const panel = this.createPanel(file, studio);
      panel.onDidDispose(() => { this.open_.delete(file); studio.stop(); });
      return { panel, studio };
    });
    this.open_.set(file, opening);
    opening.catch(() => this.open_.delete(file));   // a failed start may be retried
    return opening;
  }

  // Closes every panel (each stops its studio); resolves once all have ended.
  disposeAll() {
    const all = [...this.open_.values()].map((opening) => opening.then(
      ({ panel, studio }) => { panel.dispose(); return studio.stop(); }, () => undefined));
    return Promise.all(all);
  }
}

module.exports = { startStudio, stopProcess, studioOrigin, webviewOptions, studioHtml, StudioPanels, START_TIMEOUT_MS };
