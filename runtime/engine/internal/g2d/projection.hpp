#pragma once
// How a 3D model (a grammar declared `space 3d;`) is drawn in an SVG: an
// orthographic view from a direction (`--view-from X,Y,Z`, default
// (1, -2, 1.5): from the front right, above), z up on the page. Screen x is
// the unit vector along z × from ("right" as the viewer sees it) and screen
// y is from × right, so world z stays up unless the view is straight down
// or up (then world y is up on the page). Faces are drawn below edges and
// edges below nodes, as in 2D; within each, farther first (the depth of a
// face's corner mean, an edge's midpoint), and faces seen from their back
// (counter-clockwise corners seen from the other side) before every face
// seen from its front: on a closed surface oriented outwards they lie
// behind, however big.
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/svg_writer.hpp"

namespace g2d::rt {

struct ViewProjection {
    vec3 right{1, 0, 0}, up{0, 1, 0}, toward{0, 0, 1};   // toward: from the model to the viewer
    vec2 project(vec3 p) const { return {dot(p, right), dot(p, up)}; }
    double depth(vec3 p) const { return -dot(p, toward); }   // larger: farther away
};

inline constexpr vec3 kDefaultViewFrom{1, -2, 1.5};

// Throws std::invalid_argument for the zero vector.
ViewProjection viewFrom(vec3 from);

// Replaces the items' 2D positions (the graph's x and y) by the projection of
// their 3D positions, and sets their depth.
void projectDrawing(std::vector<DrawItem>& items, const Graph& g, const ViewProjection& view);
void projectItem(DrawItem& it, const Graph& g, const ViewProjection& view);

}  // namespace g2d::rt
