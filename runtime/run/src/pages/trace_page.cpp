// The page of `g2d run --trace OUT.html`: one self-contained file (no
// network), the trace embedded as JSON, the final SVG as g2d draws it, and a
// player that rebuilds any step from the deltas (web/view/src/trace2d.js;
// a 3D grammar's: trace3d.js in the --view page's viewer). Long runs are
// grouped into frames so the slider stays usable; the page says so.
#include "g2d/trace.hpp"

#include "g2d/svg_writer.hpp"
#include "g2d/trace_script.hpp"
#include "g2d/view_script.hpp"

namespace g2d::rt {

namespace {

// Inside <script>, "</" would end the element.
std::string scriptSafe(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '<' && i + 1 < s.size() && s[i + 1] == '/') out += "<\\";
        else out += s[i];
    }
    return out;
}

const char* const kStyle = R"CSS(
body { font: 14px system-ui, sans-serif; margin: 0; color: #222; }
header { padding: 8px 12px; background: #f4f4f4; border-bottom: 1px solid #ddd; }
main { display: flex; flex-wrap: wrap; gap: 12px; padding: 12px; }
section { flex: 1 1 420px; min-width: 320px; }
h2 { font-size: 15px; margin: 0 0 6px; }
#stage, #final svg { width: 100%; height: 60vh; border: 1px solid #ddd; background: white; }
#controls { display: flex; align-items: center; gap: 6px; margin: 8px 0; }
#slider { flex: 1; }
#info { min-height: 3em; }
#note { color: #8a5a00; }
.legend span { display: inline-block; margin-right: 12px; }
.sw { display: inline-block; width: 12px; height: 12px; vertical-align: middle; margin-right: 4px; }
)CSS";

// The 3D player: the viewer fills the window, the controls float over it.
const char* const kStyle3d = R"CSS(
html, body { margin: 0; height: 100%; overflow: hidden; background: #fff; font: 13px system-ui, sans-serif; color: #222; }
canvas { display: block; }
#legend { position: absolute; top: 8px; left: 8px; padding: 6px 10px; max-width: 46em;
  background: rgba(255, 255, 255, 0.85); border: 1px solid #ddd; border-radius: 4px; }
#controls { display: flex; align-items: center; gap: 6px; margin: 6px 0; }
#slider { flex: 1; }
#note, #status { color: #8a5a00; }
#toggles, #views { display: inline-block; margin: 4px 8px 0 0; white-space: nowrap; }
#views button { font: 12px system-ui, sans-serif; padding: 1px 6px; }
.legend span { display: inline-block; margin-right: 12px; }
.sw { display: inline-block; width: 12px; height: 12px; vertical-align: middle; margin-right: 4px; }
small { display: block; color: #666; margin-top: 2px; }
)CSS";

const char* const kControls =
    "<div id=\"controls\"><button id=\"first\">|&lt;</button><button id=\"prev\">&lt;</button>"
    "<button id=\"play\">Play</button><button id=\"next\">&gt;</button><button id=\"last\">&gt;|</button>"
    "<input id=\"slider\" type=\"range\" min=\"0\" value=\"0\"><span id=\"position\"></span></div>\n";

const char* const kMarks =
    "<p class=\"legend\">"
    "<span><i class=\"sw\" style=\"background:#ff8c00\"></i>matched and kept</span>"
    "<span><i class=\"sw\" style=\"background:#d62728\"></i>deleted</span>"
    "<span><i class=\"sw\" style=\"background:#1a9e3a\"></i>added</span>"
    "<span><i class=\"sw\" style=\"background:#1f77b4\"></i>moved</span></p>\n";

std::string tracePage3d(const std::string& traceJson, const std::string& title) {
    std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + xmlEscape(title) +
                      " — g2d trace</title>\n<style>" + kStyle3d + "</style>\n</head>\n<body>\n";
    out += "<div id=\"legend\"><strong>" + xmlEscape(title) + "</strong> — derivation trace (g2d), in 3D\n" + kControls;
    out += "<div id=\"info\"></div>\n<div id=\"note\"></div>\n" + std::string(kMarks) +
           "<small>Steps are drawn with each kind's style. Drag to turn, right-drag to pan, scroll to zoom; "
           "arrow keys step.</small><span id=\"status\">This page needs JavaScript and WebGL.</span></div>\n";
    out += "<script id=\"trace\" type=\"application/json\">" + scriptSafe(traceJson) + "</script>\n";
    out += "<script>" + viewScript() + "</script>\n</body>\n</html>\n";
    return out;
}

}  // namespace

std::string writeTracePage(const std::string& traceJson, const std::string& finalSvg, const std::string& title, bool space3d) {
    if (space3d) return tracePage3d(traceJson, title);
    // The final SVG goes inline without its XML declaration.
    std::string svg = finalSvg;
    if (svg.rfind("<?xml", 0) == 0) svg = svg.substr(svg.find('\n') + 1);
    std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + xmlEscape(title) +
                      " — g2d trace</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
    out += "<header><strong>" + xmlEscape(title) + "</strong> — derivation trace (g2d)</header>\n<main>\n";
    out += "<section>\n<h2>Step by step</h2>\n<svg id=\"stage\" xmlns=\"http://www.w3.org/2000/svg\"></svg>\n";
    out += kControls;
    out += "<div id=\"info\"></div>\n<div id=\"note\"></div>\n" + std::string(kMarks) +
           "<p>Steps are drawn with each kind's style; the final drawing, as g2d writes it, is on the right.</p>\n</section>\n";
    out += "<section id=\"final\">\n<h2>Final drawing</h2>\n" + svg + "</section>\n</main>\n";
    out += "<script id=\"trace\" type=\"application/json\">" + scriptSafe(traceJson) + "</script>\n";
    out += "<script>" + traceScript() + "</script>\n</body>\n</html>\n";
    return out;
}

}  // namespace g2d::rt
