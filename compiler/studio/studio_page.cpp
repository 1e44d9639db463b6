#include "studio/studio_page.hpp"

namespace g2d::studio {

// Images: blob: is the large-drawing preview and the downloads, data: the seeds sheet.
// Framing: the page itself, and VS Code's studio panel (editors/vscode/studio_panel.js). There the
// iframe's ancestors are the webview's frames (vscode-webview://…) and the workbench window
// (vscode-file://vscode-app), and frame-ancestors checks every one. Web pages cannot have those
// schemes, so no site can frame the studio.
const char* studioPagePolicy() {
    return "default-src 'none'; script-src 'self'; connect-src 'self'; style-src 'unsafe-inline'; img-src 'self' data: blob:; "
           "base-uri 'none'; form-action 'none'; frame-ancestors 'self' vscode-webview: vscode-file:";
}

}  // namespace g2d::studio
