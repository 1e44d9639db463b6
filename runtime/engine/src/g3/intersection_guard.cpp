#include "g2d/intersection_guard.hpp"

#include <algorithm>

#include "g2d/geometry3.hpp"

namespace g2d::rt {

namespace {

bool isSide(const Graph& g, FaceId f, NodeId u, NodeId v) {
    bool side = false;
    g.eachSideUse(u, v, [&](FaceId h, bool) { side = side || h == f; });
    return side;
}

}  // namespace

IntersectionGuard::Shape IntersectionGuard::edgeShape(const Graph& g, EdgeId e) const {
    Shape s;
    s.ends = {g.source(e), g.target(e)};
    s.points = {g.pos3(s.ends[0]), g.pos3(s.ends[1])};
    // Only edges without faces are thick (§3.2.1): the cylinder of the ends' mean radius.
    if (g.sideFaceCount(s.ends[0], s.ends[1]) == 0) s.radius = (g.radius(s.ends[0]) + g.radius(s.ends[1])) / 2;
    return s;
}

IntersectionGuard::Shape IntersectionGuard::faceShape(const Graph& g, FaceId f) const {
    Shape s;
    CornerId c = g.firstCorner(f);
    for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) s.points.push_back(g.pos3(g.cornerNode(c)));
    return s;
}

Aabb IntersectionGuard::boxOf(const Shape& s) const { return inflated(boundsOf(s.points), s.radius); }

void IntersectionGuard::begin(const Graph& g) {
    // Cells about an edge long: most boxes then cover a few cells.
    double total = 0;
    std::size_t count = 0;
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) {
            total += length(g.pos3(g.target(e)) - g.pos3(g.source(e)));
            ++count;
        }
    const double cell = count && total > 0 ? total / static_cast<double>(count) : 1.0;
    edges_.emplace(cell);
    faces_.emplace(cell);
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) edges_->insert(e, boxOf(edgeShape(g, e)));
    for (FaceId f = 0; f < g.faceCapacity(); ++f)
        if (g.faceAlive(f)) faces_->insert(f, boxOf(faceShape(g, f)));
}

bool IntersectionGuard::crosses(const Graph& g, const Shape& s, bool isFace, std::uint32_t id, const Capacities& from) const {
    const Aabb box = boxOf(s);
    std::vector<std::uint32_t> near;
    edges_->overlapping(box, near);
    for (EdgeId e : near) {
        if (!g.edgeAlive(e) || (!isFace && e == id) || e >= from[1]) continue;   // this application's own are not indexed yet
        const Shape o = edgeShape(g, e);
        if (isFace) {
            if (!isSide(g, id, o.ends[0], o.ends[1]) && segmentPolygon(o.points[0], o.points[1], s.points)) return true;
            continue;
        }
        const int shared = (o.ends[0] == s.ends[0] || o.ends[0] == s.ends[1]) + (o.ends[1] == s.ends[0] || o.ends[1] == s.ends[1]);
        const double h = s.radius + o.radius;
        if (shared == 2) continue;   // the same ends: no new geometry
        if (shared == 1) {
            const NodeId at = (o.ends[0] == s.ends[0] || o.ends[0] == s.ends[1]) ? o.ends[0] : o.ends[1];
            const vec3 a = g.pos3(s.ends[0] == at ? s.ends[1] : s.ends[0]), b = g.pos3(o.ends[0] == at ? o.ends[1] : o.ends[0]);
            if (segmentsIntersectSharing(g.pos3(at), a, b, h)) return true;
        } else if (segmentsIntersect(s.points[0], s.points[1], o.points[0], o.points[1], h)) {
            return true;
        }
    }
    faces_->overlapping(box, near);
    for (FaceId f : near) {
        if (!g.faceAlive(f) || (isFace && f == id) || f >= from[2]) continue;
        const Shape o = faceShape(g, f);
        if (isFace ? polygonsIntersect(s.points, o.points)
                   : !isSide(g, f, s.ends[0], s.ends[1]) && segmentPolygon(s.points[0], s.points[1], o.points))
            return true;
    }
    return false;
}

bool IntersectionGuard::admit(Graph& g, const Capacities& from, const Capacities& to) {
    bool hit = false;
    for (EdgeId e = static_cast<EdgeId>(from[1]); e < to[1] && !hit; ++e)
        if (g.edgeAlive(e)) hit = crosses(g, edgeShape(g, e), false, e, from);
    for (FaceId f = static_cast<FaceId>(from[2]); f < to[2] && !hit; ++f)
        if (g.faceAlive(f)) hit = crosses(g, faceShape(g, f), true, f, from);
    if (hit) {
        for (FaceId f = static_cast<FaceId>(from[2]); f < to[2]; ++f)
            if (g.faceAlive(f)) g.removeFace(f);
        for (EdgeId e = static_cast<EdgeId>(from[1]); e < to[1]; ++e)
            if (g.edgeAlive(e)) g.removeEdge(e);
        for (NodeId n = static_cast<NodeId>(from[0]); n < to[0]; ++n)
            if (g.nodeAlive(n)) g.removeNode(n);
        ++cancelled_;
        return false;
    }
    for (EdgeId e = static_cast<EdgeId>(from[1]); e < to[1]; ++e)
        if (g.edgeAlive(e)) edges_->insert(e, boxOf(edgeShape(g, e)));
    for (FaceId f = static_cast<FaceId>(from[2]); f < to[2]; ++f)
        if (g.faceAlive(f)) faces_->insert(f, boxOf(faceShape(g, f)));
    return true;
}

}  // namespace g2d::rt
