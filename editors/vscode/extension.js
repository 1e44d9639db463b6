// Starts `g2d lsp` (the compiler's own language server) for .g2d files:
// errors as you type, hover, go to definition, outline and completion.
// "g2d: Open Studio" shows `g2d studio` for the active file in a webview
// (studio_panel.js). The executable is the setting `g2d.path` (default:
// `g2d` on the PATH).
"use strict";
const path = require("path");
const vscode = require("vscode");
const { LanguageClient, TransportKind } = require("vscode-languageclient/node");
const { startStudio, studioHtml, webviewOptions, StudioPanels } = require("./studio_panel");

let client;
let studios;

function g2dCommand() {
  return vscode.workspace.getConfiguration("g2d").get("path") || "g2d";
}

function createStudioPanel(file, studio) {
  const title = `Studio: ${path.basename(file)}`;
  const panel = vscode.window.createWebviewPanel("g2d.studio", title, vscode.ViewColumn.Beside,
                                                 webviewOptions(studio.port));
  panel.webview.html = studioHtml(studio.url, title);
  return panel;
}

// The studio edits the file on disk and reloads when it changes there, so the
// editor's text is saved first: both then start from the same text, and stay
// in step through the file. From the editor's title bar the command gets
// the editor's file; from the command palette it takes the active editor's.
async function openStudio(uri) {
  const editor = vscode.window.activeTextEditor;
  const document = uri instanceof vscode.Uri ? await vscode.workspace.openTextDocument(uri) : editor && editor.document;
  if (!document || document.languageId !== "g2d") {
    vscode.window.showErrorMessage("g2d: Open Studio needs a .g2d file in the active editor.");
    return;
  }
  if (document.isUntitled || document.uri.scheme !== "file") {
    vscode.window.showErrorMessage("g2d: save the grammar to a file before opening the studio.");
    return;
  }
  if (document.isDirty && !(await document.save())) {
    vscode.window.showErrorMessage(`g2d: cannot save ${document.uri.fsPath}, so the studio was not opened.`);
    return;
  }
  try {
    await studios.open(document.uri.fsPath);
  } catch (err) {
    vscode.window.showErrorMessage(`g2d: cannot open the studio: ${err.message}. Set "g2d.path" to the g2d executable.`);
  }
}

function activate(context) {
  const command = g2dCommand();
  const serverOptions = { command, args: ["lsp"], transport: TransportKind.stdio };
  const clientOptions = { documentSelector: [{ scheme: "file", language: "g2d" }, { scheme: "untitled", language: "g2d" }] };
  client = new LanguageClient("g2d", "g2d language server", serverOptions, clientOptions);
  client.start().catch((err) => {
    vscode.window.showErrorMessage(
      `g2d: cannot start \`${command} lsp\` (${err.message}). Set "g2d.path" to the g2d executable.`);
  });
  context.subscriptions.push({ dispose: () => client && client.stop() });

  studios = new StudioPanels({ start: (file) => startStudio(g2dCommand(), file), createPanel: createStudioPanel });
  context.subscriptions.push(vscode.commands.registerCommand("g2d.openStudio", openStudio));
}

function deactivate() {
  const stopping = [studios ? studios.disposeAll() : undefined, client ? client.stop() : undefined];
  return Promise.all(stopping);
}

module.exports = { activate, deactivate };
