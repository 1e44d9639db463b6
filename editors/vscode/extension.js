// Starts `g2d lsp` (the compiler's own language server) for .g2d files:
// errors as you type, hover, go to definition, outline and completion.
// The executable is the setting `g2d.path` (default: `g2d` on the PATH).
"use strict";
const vscode = require("vscode");
const { LanguageClient, TransportKind } = require("vscode-languageclient/node");

let client;

function activate(context) {
  const command = vscode.workspace.getConfiguration("g2d").get("path") || "g2d";
  const serverOptions = { command, args: ["lsp"], transport: TransportKind.stdio };
  const clientOptions = { documentSelector: [{ scheme: "file", language: "g2d" }, { scheme: "untitled", language: "g2d" }] };
  client = new LanguageClient("g2d", "g2d language server", serverOptions, clientOptions);
  client.start().catch((err) => {
    vscode.window.showErrorMessage(
      `g2d: cannot start \`${command} lsp\` (${err.message}). Set "g2d.path" to the g2d executable.`);
  });
  context.subscriptions.push({ dispose: () => client && client.stop() });
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
