#pragma once
// Writes the drawing of a graph as SVG. Each element becomes one SVG element
// chosen by its `tag` style property; the other properties become SVG
// attributes (`_` → `-`). Graph coordinates are used directly inside a group
// that flips y, so y points up as in the grammar; 1 unit is drawn as 1 cm.
//
// Properties with a meaning of their own:
//   tag     circle | line | rect | path | image | text | polyline | none
//           (default: circle for nodes, line for edges, polygon for faces;
//           a face with holes, Graph::faceHoles, is one path of its rings
//           with fill-rule evenodd)
//   r       circle radius (default 0.1)
//   width, height   rect and image size, centred on the node
//   rotate  degrees, counter-clockwise, about the node (rect, image, text)
//   href    image source;  text  the text of a text element
//   d       path data, points  polyline points (graph coordinates)
//   arrow   true: directed edges end in an arrowhead
//   z       drawing order (lower first; then faces, edges, nodes, each by id;
//           in 3D all three together, farther first: projection.hpp)
//   filter  an id of a filter in `defs` (written as url(#id)) or any CSS filter
//
// The compact form (SvgOptions::compact) writes each run of consecutive plain
// lines (edges drawn as `line`, without an arrow or a fill) with the same
// attributes as one <path> of `M x y L x y` segments, a segment that starts
// where the last ended continuing it (`L x y x y`); every other item is
// written as usual. `precision` rounds coordinates to that many decimals.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/text_out.hpp"
#include "g2d/view_box.hpp"

namespace g2d::rt {

struct DrawItem {
    ElemClass cls = ElemClass::Node;
    std::uint32_t id = 0;
    vec2 a{0, 0}, b{0, 0};                 // node position, or edge endpoints (a face: its corner mean)
    std::vector<vec2> corners;             // a face's corners, in order
    std::vector<std::vector<vec2>> holes;  // a face's holes (Graph::faceHoles), each a ring
    std::vector<vec2> bend;                // an edge's bend points between a and b (Graph::edgeBend)
    std::vector<StyleOverride> props;      // resolved: kind defaults, then overrides (enums as strings)
    double depth = 0;                      // 3D: the distance from the viewer (farther drawn first)
    bool turnedAway = false;               // 3D: a face seen from its back (drawn before those seen from the front)
    bool inDepth = false;                  // 3D: faces, edges and nodes painted together by depth (projection.hpp)
};

struct SvgOptions {
    bool compact = false;
    std::optional<int> precision;   // decimals of coordinates (none: the shortest exact text)
    // What an image's href becomes in the file (image_links.hpp); none: as written.
    std::function<std::string(const std::string&)> imageHref;
    // The viewBox, exactly (view_box.hpp); none: fitted to the drawing, with a margin.
    std::optional<ViewBox> viewBox;
};

// Makes the item of live element `id` of class `cls` in `out` (its storage reused).
using ItemMaker = std::function<void(ElemClass cls, std::uint32_t id, DrawItem& out)>;

// All items at hand (the trace player, tests).
std::string writeSvg(std::vector<DrawItem> items, const std::vector<std::string>& defs, const SvgOptions& options = {});

// The drawing of every live element of `g`, streamed: each item is made
// twice, once to fit the frame and once to be written, and none is kept (the
// order is kept as compact keys, and not at all while it is the graph's own).
// Writes the same bytes as the function above given all items.
void writeSvg(const Graph& g, const ItemMaker& make, const std::vector<std::string>& defs, TextOut& out,
              const SvgOptions& options = {});

// A resolved style property of an item (nullptr / the fallback when absent;
// numbers accept int or float values). The trace player reads kinds' looks too.
const Value* styleValue(const DrawItem& it, std::string_view prop);
double styleNumber(const DrawItem& it, const char* prop, double fallback);
std::string styleText(const DrawItem& it, const char* prop, const std::string& fallback);

// XML-escapes text for attribute values and element content.
std::string xmlEscape(const std::string& s);

}  // namespace g2d::rt
