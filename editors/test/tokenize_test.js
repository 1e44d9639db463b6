#!/usr/bin/env node
// The TextMate grammar as VS Code runs it (vscode-textmate on the Oniguruma
// WebAssembly build, from npm): every example and the stdlib tokenise
// without a token left unscoped or a rule stack left open, and the fixture
// covering every construct of docs/language.md gets the expected scopes.
// Also loads extension.js against a stand-in `vscode` module and checks
// that it starts `g2d lsp`.
// usage: node editors/test/tokenize_test.js   (after npm ci in editors/vscode)
"use strict";
const fs = require("fs");
const path = require("path");
const Module = require("module");

const editors = path.dirname(__dirname);
const root = path.dirname(editors);
const vscodeDir = path.join(editors, "vscode");
const requireFromExtension = Module.createRequire(path.join(vscodeDir, "package.json"));
const vsctm = requireFromExtension("vscode-textmate");
const oniguruma = requireFromExtension("vscode-oniguruma");

let failed = 0, passed = 0;
function check(ok, what) {
  if (ok) passed++;
  else { failed++; console.log("FAIL: " + what); }
}

async function main() {
  const wasm = fs.readFileSync(path.join(path.dirname(requireFromExtension.resolve("vscode-oniguruma")), "onig.wasm"));
  await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
  const registry = new vsctm.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (sources) => new oniguruma.OnigScanner(sources),
      createOnigString: (s) => new oniguruma.OnigString(s),
    }),
    loadGrammar: async (scope) => scope === "source.g2d"
      ? vsctm.parseRawGrammar(fs.readFileSync(path.join(vscodeDir, "syntaxes/g2d.tmLanguage.json"), "utf8"), "g2d.tmLanguage.json")
      : null,
  });
  const grammar = await registry.loadGrammar("source.g2d");

  // Tokens of a file: [{text, scopes, line}]
  function tokenize(text) {
    let stack = vsctm.INITIAL;
    const out = [];
    text.split(/\r?\n/).forEach((line, i) => {
      const r = grammar.tokenizeLine(line, stack);
      for (const t of r.tokens) out.push({ text: line.slice(t.startIndex, t.endIndex), scopes: t.scopes, line: i + 1 });
      stack = r.ruleStack;
    });
    return { tokens: out, finalDepth: stack.depth };
  }

  // Every example and stdlib file: no rule left open at the end, and every
  // keyword of grammar/G2d.g4 (its identifier-like literals) highlighted as one.
  const g4 = fs.readFileSync(path.join(root, "grammar/G2d.g4"), "utf8");
  const keywords = new Set([...g4.matchAll(/'([A-Za-z_][A-Za-z0-9_]*)'/g)].map((m) => m[1]));
  check(keywords.has("rule") && keywords.has("produce"), "keywords read from grammar/G2d.g4");
  const keywordScope = (scopes) => scopes.some((s) => /^(keyword|storage|constant\.language)\b/.test(s));
  // Keywords G2d.g4 also accepts as a parameter's name (`param merge: bool`).
  const nameKeywords = new Set(["merge"]);
  const files = [...fs.readdirSync(path.join(root, "examples")).filter((f) => f.endsWith(".g2d")).map((f) => path.join(root, "examples", f)),
                 ...fs.readdirSync(path.join(root, "stdlib")).filter((f) => f.endsWith(".g2d")).map((f) => path.join(root, "stdlib", f)),
                 path.join(__dirname, "fixture.g2d")];
  for (const file of files) {
    const { tokens, finalDepth } = tokenize(fs.readFileSync(file, "utf8"));
    const name = path.relative(root, file);
    check(finalDepth === 1, `${name}: a rule is still open at the end (depth ${finalDepth})`);
    const missed = tokens.filter((t) => keywords.has(t.text.trim()) && !keywordScope(t.scopes) &&
                                        !(nameKeywords.has(t.text.trim()) && t.scopes.some((s) => /^variable/.test(s))) &&
                                        !t.scopes.some((s) => /^(comment|string)/.test(s)));
    check(missed.length === 0, `${name}: keywords not highlighted ${JSON.stringify(missed.slice(0, 5).map((t) => t.line + ":" + t.text.trim() + " " + t.scopes.join(" ")))}`);
  }

  // The fixture: chosen tokens and the scope each must carry.
  const fixture = tokenize(fs.readFileSync(path.join(__dirname, "fixture.g2d"), "utf8"));
  if (process.argv[2] === "--dump") {
    for (const t of fixture.tokens) if (t.text.trim()) console.log(JSON.stringify([t.line, t.text, t.scopes.slice(1).join(" ")]));
    return;
  }
  const expected = JSON.parse(fs.readFileSync(path.join(__dirname, "fixture.scopes.json"), "utf8"));
  for (const [line, text, scope] of expected) {
    const token = fixture.tokens.find((t) => t.line === line && t.text === text);
    check(token && token.scopes.some((s) => s === scope || s.startsWith(scope + ".")),
      `fixture line ${line}: \`${text}\` should be ${scope}, is ${token ? token.scopes.join(" ") : "not a token"}`);
  }

  // extension.js with a stand-in vscode module: activation starts `g2d lsp`.
  const started = [];
  const fakeVscode = {
    workspace: { getConfiguration: () => ({ get: () => "/opt/g2d/bin/g2d" }) },
    window: { showErrorMessage: () => {} },
    commands: { registerCommand: () => ({ dispose() {} }) },   // g2d.openStudio: editors/test/studio_panel_test.js
  };
  const originalLoad = Module._load;
  Module._load = function (request, parent, isMain) {
    if (request === "vscode") return fakeVscode;
    if (request === "vscode-languageclient/node") {
      return {
        TransportKind: { stdio: 0 },
        LanguageClient: class {
          constructor(id, name, server, client) { started.push({ id, server, client }); }
          start() { return Promise.resolve(); }
          stop() { return Promise.resolve(); }
        },
      };
    }
    return originalLoad.apply(this, arguments);
  };
  const extension = require(path.join(vscodeDir, "extension.js"));
  extension.activate({ subscriptions: [] });
  Module._load = originalLoad;
  check(started.length === 1 && started[0].server.command === "/opt/g2d/bin/g2d" &&
        JSON.stringify(started[0].server.args) === '["lsp"]' &&
        started[0].client.documentSelector.some((d) => d.language === "g2d"),
        "extension.js should start `g2d lsp` for g2d documents: " + JSON.stringify(started));

  // Snippets: a production, a node kind, an edge kind and an axiom.
  const snippets = JSON.parse(fs.readFileSync(path.join(vscodeDir, "snippets/g2d.json"), "utf8"));
  const prefixes = Object.values(snippets).map((s) => s.prefix);
  for (const p of ["rule", "node", "edge", "axiom"]) check(prefixes.includes(p), `a snippet with prefix ${p}`);

  console.log(`${passed} passed, ${failed} failed`);
  process.exit(failed ? 1 : 0);
}

main().catch((e) => { console.log("FAIL: " + (e.stack || e)); process.exit(1); });
