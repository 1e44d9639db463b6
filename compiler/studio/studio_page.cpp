#include "studio/studio_page.hpp"

namespace g2d::studio {

// A first page that shows the API at work: a plain text area (CodeMirror,
// parameters, the player and the seeds sheet come next), the picture and
// the diagnostics.
const std::string& studioPage() {
    static const std::string page = R"HTML(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>g2d studio</title>
<link rel="icon" href="data:,">
<style>
  body { margin: 0; font: 14px system-ui, sans-serif; display: grid; grid-template-columns: minmax(20em, 1fr) 2fr;
         grid-template-rows: auto 1fr auto; height: 100vh; }
  header { grid-column: 1 / 3; padding: 4px 8px; border-bottom: 1px solid #ccc; display: flex; gap: 1em; align-items: center; }
  #editor { font: 13px ui-monospace, monospace; border: 0; border-right: 1px solid #ccc; padding: 6px; resize: none; }
  #picture { overflow: auto; display: flex; align-items: center; justify-content: center; }
  #picture svg { width: 100%; height: 100%; }
  #diagnostics { grid-column: 1 / 3; margin: 0; padding: 4px 8px; border-top: 1px solid #ccc; max-height: 10em; overflow: auto;
                 list-style: none; font: 12px ui-monospace, monospace; }
  .error { color: #b00; } .warning { color: #a60; } #status { color: #555; }
</style>
</head>
<body>
<header><strong id="file">g2d studio</strong><button id="save" type="button">Save</button><span id="status">Loading…</span></header>
<textarea id="editor" spellcheck="false" wrap="off" aria-label="Grammar"></textarea>
<main id="picture" aria-label="Picture"></main>
<ul id="diagnostics" aria-label="Diagnostics"></ul>
<script src="/studio.js"></script>
</body>
</html>
)HTML";
    return page;
}

// Framing: the page itself, and VS Code's studio panel (editors/vscode/studio_panel.js). There the
// iframe's ancestors are the webview's frames (vscode-webview://…) and the workbench window
// (vscode-file://vscode-app), and frame-ancestors checks every one. Web pages cannot have those
// schemes, so no site can frame the studio.
const char* studioPagePolicy() {
    return "default-src 'none'; script-src 'self'; connect-src 'self'; style-src 'unsafe-inline'; img-src 'self' data:; "
           "base-uri 'none'; form-action 'none'; frame-ancestors 'self' vscode-webview: vscode-file:";
}

}  // namespace g2d::studio
