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

template <class Ids>
void sortUnique(Ids& ids) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

}  // namespace

IntersectionGuard::Shape IntersectionGuard::edgeShape(const Graph& g, EdgeId e) const {
    Shape s;
    s.nodes = {g.source(e), g.target(e)};
    s.points = {g.pos3(s.nodes[0]), g.pos3(s.nodes[1])};
    // Only edges without faces are thick (§3.2.1): the cylinder of the ends' mean radius.
    if (g.sideFaceCount(s.nodes[0], s.nodes[1]) == 0) s.radius = (g.radius(s.nodes[0]) + g.radius(s.nodes[1])) / 2;
    return s;
}

IntersectionGuard::Shape IntersectionGuard::faceShape(const Graph& g, FaceId f) const {
    Shape s;
    CornerId c = g.firstCorner(f);
    for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) {
        s.nodes.push_back(g.cornerNode(c));
        s.points.push_back(g.pos3(s.nodes.back()));
    }
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

void IntersectionGuard::changed(const Graph& g, const GraphJournal& j, std::vector<EdgeId>& edges, std::vector<FaceId>& faces) const {
    for (EdgeId e = static_cast<EdgeId>(j.from[1]); e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) edges.push_back(e);
    for (FaceId f = static_cast<FaceId>(j.from[2]); f < g.faceCapacity(); ++f)
        if (g.faceAlive(f)) faces.push_back(f);
    for (const GraphJournal::Entry& entry : j.entries) {
        switch (entry.op) {
        case GraphJournal::Op::Node:   // moved, or a new radius: its edges and faces
            if (!g.nodeAlive(entry.id)) break;
            for (EdgeId e : g.incident(entry.id)) edges.push_back(e);
            for (CornerId c = g.firstCornerAt(entry.id); c != kNoId; c = g.nextCornerAt(c)) faces.push_back(g.cornerFace(c));
            break;
        case GraphJournal::Op::Edge:
            if (g.edgeAlive(entry.id)) edges.push_back(entry.id);
            break;
        case GraphJournal::Op::Corner:
            if (g.faceAlive(g.cornerFace(entry.id))) faces.push_back(g.cornerFace(entry.id));
            break;
        case GraphJournal::Op::FaceRemoved:
            break;
        }
    }
    sortUnique(edges);
    sortUnique(faces);
}

bool IntersectionGuard::edgeMeetsFace(const Graph& g, const Shape& edge, FaceId f, const Shape& face) const {
    if (isSide(g, f, edge.nodes[0], edge.nodes[1])) return false;
    if (plane_) return segmentCrossesOutline(edge.points[0], edge.points[1], face.points);
    const auto corner = [&](NodeId n) { return std::find(face.nodes.begin(), face.nodes.end(), n) != face.nodes.end(); };
    const bool first = corner(edge.nodes[0]), second = corner(edge.nodes[1]);
    if (first && second) return segmentPolygon(edge.points[0], edge.points[1], face.points);   // a chord
    return thickSegmentPolygon(edge.points[0], edge.points[1], edge.radius, first ? 0 : second ? 1 : -1, face.points);
}

bool IntersectionGuard::crosses(const Graph& g, const Shape& s, bool isFace, std::uint32_t id,
                                const GraphJournal::Capacities& from) const {
    const Aabb box = boxOf(s);
    std::vector<std::uint32_t> near;
    edges_->overlapping(box, near);
    for (EdgeId e : near) {
        if (!g.edgeAlive(e) || (!isFace && e == id) || e >= from[1]) continue;   // this application's new ones are not indexed yet
        const Shape o = edgeShape(g, e);
        if (isFace) {
            if (edgeMeetsFace(g, o, id, s)) return true;
            continue;
        }
        const int shared = (o.nodes[0] == s.nodes[0] || o.nodes[0] == s.nodes[1]) + (o.nodes[1] == s.nodes[0] || o.nodes[1] == s.nodes[1]);
        const double h = s.radius + o.radius;
        if (shared == 2) continue;   // the same ends: no new geometry
        if (shared == 1) {
            const NodeId at = (o.nodes[0] == s.nodes[0] || o.nodes[0] == s.nodes[1]) ? o.nodes[0] : o.nodes[1];
            const vec3 a = g.pos3(s.nodes[0] == at ? s.nodes[1] : s.nodes[0]), b = g.pos3(o.nodes[0] == at ? o.nodes[1] : o.nodes[0]);
            if (segmentsIntersectSharing(g.pos3(at), a, b, h)) return true;
        } else if (segmentsIntersect(s.points[0], s.points[1], o.points[0], o.points[1], h)) {
            return true;
        }
    }
    faces_->overlapping(box, near);
    for (FaceId f : near) {
        if (!g.faceAlive(f) || (isFace && f == id) || f >= from[2]) continue;
        const Shape o = faceShape(g, f);
        if (!isFace ? edgeMeetsFace(g, s, f, o) : plane_ ? outlinesCross(s.points, o.points) : polygonsIntersect(s.points, o.points))
            return true;
    }
    return false;
}

bool IntersectionGuard::admit(Graph& g) {
    const GraphJournal& j = *g.journal();
    const GraphJournal::Capacities from = j.from;
    std::vector<EdgeId> edges;
    std::vector<FaceId> faces;
    changed(g, j, edges, faces);
    // Older elements it changed are indexed where they are now (as well as
    // where they were), so that they find each other.
    for (EdgeId e : edges)
        if (e < from[1]) edges_->insert(e, boxOf(edgeShape(g, e)));
    for (FaceId f : faces)
        if (f < from[2]) faces_->insert(f, boxOf(faceShape(g, f)));
    bool hit = false;
    for (std::size_t i = 0; i < edges.size() && !hit; ++i) hit = crosses(g, edgeShape(g, edges[i]), false, edges[i], from);
    for (std::size_t i = 0; i < faces.size() && !hit; ++i) hit = crosses(g, faceShape(g, faces[i]), true, faces[i], from);
    g.endJournal(hit);
    if (hit) {
        ++cancelled_;
        return false;
    }
    for (EdgeId e : edges)
        if (e >= from[1]) edges_->insert(e, boxOf(edgeShape(g, e)));
    for (FaceId f : faces)
        if (f >= from[2]) faces_->insert(f, boxOf(faceShape(g, f)));
    return true;
}

}  // namespace g2d::rt
