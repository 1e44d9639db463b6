#pragma once
// How a 3D model (a grammar declared `space 3d;`) is drawn in an SVG: an
// orthographic view from a direction (`--view-from X,Y,Z`, default
// (1, -2, 1.5): from the front right, above), z up on the page. Screen x is
// the unit vector along z × from ("right" as the viewer sees it) and screen
// y is from × right, so world z stays up unless the view is straight down
// or up (then world y is up on the page). Faces, edges and nodes are
// painted together, farther first (the depth of a face's corner mean, an
// edge's midpoint, a node), so that a face hides what lies behind it:
// - the faces of a solid (SolidFaces) seen from their back come before
//   everything else: they lie behind its front, however big;
// - an edge or node on faces is painted with the nearest of them (not backs
//   of solids), right after it: at one depth faces come before edges, edges
//   before nodes, so a face's sides and corners are never under it; one on
//   a solid's back faces only goes with those, below its front (a hidden edge);
// - a node also comes right after its nearest edge at the latest, so it
//   stays on top of its edges.
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

// The faces whose back is known to lie behind: those of closed surfaces
// (each side run by exactly one other face, the other way) oriented outwards
// (enclosing a positive volume). An open surface or one oriented inwards
// (an open box, a room seen from outside) is seen from either side, so its
// faces are painted by depth alone.
class SolidFaces {
public:
    explicit SolidFaces(const Graph& g);
    // f is a solid's face seen from its back.
    bool backOf(const Graph& g, FaceId f, const ViewProjection& view) const;

private:
    std::vector<bool> solid_;   // by face id
};

// Replaces the items' 2D positions (the graph's x and y) by the projection of
// their 3D positions, and sets their depth. `solid`: SolidFaces of g, made
// once per drawing.
void projectDrawing(std::vector<DrawItem>& items, const Graph& g, const ViewProjection& view);
void projectItem(DrawItem& it, const Graph& g, const ViewProjection& view, const SolidFaces& solid);

}  // namespace g2d::rt
