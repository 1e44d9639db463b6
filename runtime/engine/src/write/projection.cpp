#include "g2d/projection.hpp"

#include <cmath>
#include <stdexcept>

namespace g2d::rt {

ViewProjection viewFrom(vec3 from) {
    const double len = length(from);
    if (!(len > 0) || !std::isfinite(len)) throw std::invalid_argument("the view direction must be a nonzero finite vector");
    ViewProjection v;
    v.toward = from / len;
    // Straight down or up: the page's up is world y.
    const vec3 worldUp = std::abs(v.toward.z) > 1 - 1e-12 ? vec3{0, 1, 0} : vec3{0, 0, 1};
    v.right = normalize(cross(worldUp, v.toward));
    v.up = cross(v.toward, v.right);
    return v;
}

void projectDrawing(std::vector<DrawItem>& items, const Graph& g, const ViewProjection& view) {
    for (auto& it : items) projectItem(it, g, view);
}

void projectItem(DrawItem& it, const Graph& g, const ViewProjection& view) {
    if (it.cls == ElemClass::Node) {
        it.a = it.b = view.project(g.pos3(it.id));
        it.depth = view.depth(g.pos3(it.id));
    } else if (it.cls == ElemClass::Edge) {
        const vec3 a = g.pos3(g.source(it.id)), b = g.pos3(g.target(it.id));
        it.a = view.project(a);
        it.b = view.project(b);
        it.depth = view.depth((a + b) / 2.0);
    } else {
        it.corners.clear();
        CornerId c = g.firstCorner(it.id);
        for (int i = 0; i < g.cornerCount(it.id); ++i, c = g.nextCorner(c)) it.corners.push_back(view.project(g.pos3(g.cornerNode(c))));
        const vec3 centre = g.centroid3(it.id);
        it.a = it.b = view.project(centre);
        it.depth = view.depth(centre);
        it.turnedAway = dot(g.vectorArea(it.id), view.toward) < 0;
    }
}

}  // namespace g2d::rt
