#pragma once
// One drawn item as SVG text (svg_writer.hpp describes the tags), and what it
// adds to the drawing's frame. The writers (all items in memory, or streamed
// from a graph) share it, so both write the same bytes.
#include <limits>
#include <string>

#include "g2d/svg_writer.hpp"
#include "g2d/text_out.hpp"

namespace g2d::rt {

// What the frame (the viewBox and the defs) depends on.
struct SvgFrame {
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;   // the drawn extent
    double maxStroke = 0;
    bool arrows = false;   // the arrowhead marker is needed

    void add(vec2 p, double pad) { add(p, pad, pad); }
    void add(vec2 p, double halfWidth, double halfHeight);
    // A w × h box centred at c, turned by `degrees`: its corners' extent.
    void addTurned(vec2 c, double w, double h, double degrees);
    bool empty() const { return x0 > x1; }
};

// Adds the item to the frame; false if it is not written at all (tag "none",
// or a tag for another class of element).
bool measureItem(const DrawItem& it, SvgFrame& frame);

// The document's start (the XML declaration, <svg> with the viewBox: `fixed`,
// or else fitted to the frame; the defs) and end.
void writeSvgStart(const SvgFrame& frame, const std::optional<ViewBox>& fixed, const std::vector<std::string>& defs,
                   TextOut& out);
void writeSvgEnd(TextOut& out);

// Writes items in drawing order. In the compact form, runs of consecutive
// plain lines with the same attributes become one <path>; finish() ends the
// last run.
class SvgBody {
public:
    SvgBody(TextOut& out, const SvgOptions& options);
    void item(const DrawItem& it);
    void finish();

private:
    void coord(double x);
    void point(vec2 p, char between);
    void ringsPath(const DrawItem& it);
    void element(const DrawItem& it);
    void decorations(const DrawItem& it);
    void continueRun(const DrawItem& it);

    TextOut& out_;
    SvgOptions options_;
    double scale_ = 1;          // 10^precision
    StringOut attrs_;           // the compact form: the current line's attributes
    std::string runAttrs_;      // … and those of the open <path>
    vec2 runEnd_{0, 0};
    long runSegments_ = 0;      // 0: no <path> open
};

}  // namespace g2d::rt
