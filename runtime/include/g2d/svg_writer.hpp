#pragma once
// Writes the drawing of a graph as SVG. Each element becomes one SVG element
// chosen by its `tag` style property; the other properties become SVG
// attributes (`_` → `-`). Graph coordinates are used directly inside a group
// that flips y, so y points up as in the grammar; 1 unit is drawn as 1 cm.
//
// Properties with a meaning of their own:
//   tag     circle | line | rect | path | image | text | polyline | none
//           (default: circle for nodes, line for edges)
//   r       circle radius (default 0.1)
//   width, height   rect and image size, centred on the node
//   rotate  degrees, counter-clockwise, about the node (rect, image, text)
//   href    image source;  text  the text of a text element
//   d       path data, points  polyline points (graph coordinates)
//   arrow   true: directed edges end in an arrowhead
//   z       drawing order (lower first; then faces, edges, nodes; then, in 3D,
//           farther first; then by id)
//   filter  an id of a filter in `defs` (written as url(#id)) or any CSS filter
#include <string>
#include <vector>

#include "g2d/graph.hpp"

namespace g2d::rt {

struct DrawItem {
    ElemClass cls = ElemClass::Node;
    std::uint32_t id = 0;
    vec2 a{0, 0}, b{0, 0};                 // node position, or edge endpoints (a face: its corner mean)
    std::vector<vec2> corners;             // a face's corners, in order
    std::vector<StyleOverride> props;      // resolved: kind defaults, then overrides (enums as strings)
    double depth = 0;                      // 3D: the distance from the viewer (farther drawn first)
    bool turnedAway = false;               // 3D: a face seen from its back (drawn before those seen from the front)
};

std::string writeSvg(std::vector<DrawItem> items, const std::vector<std::string>& defs);

// A resolved style property of an item (nullptr / the fallback when absent;
// numbers accept int or float values). The trace player reads kinds' looks too.
const Value* styleValue(const DrawItem& it, const char* prop);
double styleNumber(const DrawItem& it, const char* prop, double fallback);
std::string styleText(const DrawItem& it, const char* prop, const std::string& fallback);

// XML-escapes text for attribute values and element content.
std::string xmlEscape(const std::string& s);

}  // namespace g2d::rt
