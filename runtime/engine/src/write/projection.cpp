#include "g2d/projection.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

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
    const SolidFaces solid(g);
    for (auto& it : items) projectItem(it, g, view, solid);
}

namespace {

// The sides of a face, as (from, to) node pairs: its outline, then its holes.
template <class Fn>
void forEachSide(const Graph& g, FaceId f, Fn fn) {
    CornerId c = g.firstCorner(f);
    for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) fn(g.cornerNode(c), g.cornerNode(g.nextCorner(c)));
    for (const std::vector<NodeId>& ring : g.faceHoles(f))
        for (std::size_t i = 0; i < ring.size(); ++i) fn(ring[i], ring[(i + 1) % ring.size()]);
}

std::uint64_t sideKey(NodeId a, NodeId b) { return (std::uint64_t{a} << 32) | b; }

FaceId findRoot(std::vector<FaceId>& parent, FaceId f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
}

// Where an edge or node on faces is painted: with the nearest face it bounds
// that is not the back of a solid, unless it lies nearer itself. A face's
// sides and corners so come right after the face (drawnBefore puts edges and
// nodes after faces at one depth) and stay on top of it; those on the back of
// a solid only go with that back, below its front (hidden edges).
struct FaceDepths {
    double front = 0, back = 0;
    bool anyFront = false, anyBack = false;
    void add(const Graph& g, FaceId f, const ViewProjection& view, const SolidFaces& solid) {
        const double d = view.depth(g.centroid3(f));
        if (solid.backOf(g, f, view)) {
            back = anyBack ? std::min(back, d) : d;
            anyBack = true;
        } else {
            front = anyFront ? std::min(front, d) : d;
            anyFront = true;
        }
    }
    void apply(DrawItem& it) const {
        if (anyFront) {
            it.depth = std::min(it.depth, front);
        } else if (anyBack) {
            it.depth = std::min(it.depth, back);
            it.turnedAway = true;
        }
    }
};

}  // namespace

SolidFaces::SolidFaces(const Graph& g) : solid_(g.faceCapacity(), false) {
    // Each side a face runs, counted: a closed surface runs each side once each way.
    std::unordered_map<std::uint64_t, int> runs;
    for (FaceId f = 0; f < g.faceCapacity(); ++f)
        if (g.faceAlive(f)) forEachSide(g, f, [&](NodeId a, NodeId b) { ++runs[sideKey(a, b)]; });
    std::unordered_map<std::uint64_t, FaceId> runner;   // a side's face, to join it to the face across
    for (FaceId f = 0; f < g.faceCapacity(); ++f)
        if (g.faceAlive(f)) forEachSide(g, f, [&](NodeId a, NodeId b) { runner[sideKey(a, b)] = f; });
    std::vector<FaceId> parent(g.faceCapacity());
    std::vector<bool> open(g.faceCapacity(), false);
    for (FaceId f = 0; f < g.faceCapacity(); ++f) parent[f] = f;
    for (FaceId f = 0; f < g.faceCapacity(); ++f) {
        if (!g.faceAlive(f)) continue;
        forEachSide(g, f, [&](NodeId a, NodeId b) {
            const auto across = runs.find(sideKey(b, a));
            if (runs[sideKey(a, b)] != 1 || across == runs.end() || across->second != 1) {
                open[f] = true;
                return;
            }
            parent[findRoot(parent, f)] = findRoot(parent, runner[sideKey(b, a)]);
        });
    }
    // A surface is closed when none of its faces has an open side; oriented
    // outwards when it encloses a positive volume (divergence theorem).
    std::vector<double> volume(g.faceCapacity(), 0);
    std::vector<bool> closed(g.faceCapacity(), true);
    for (FaceId f = 0; f < g.faceCapacity(); ++f) {
        if (!g.faceAlive(f)) continue;
        const FaceId root = findRoot(parent, f);
        volume[root] += dot(g.centroid3(f), g.vectorArea(f)) / 3;
        if (open[f]) closed[root] = false;
    }
    for (FaceId f = 0; f < g.faceCapacity(); ++f)
        if (g.faceAlive(f)) {
            const FaceId root = findRoot(parent, f);
            solid_[f] = closed[root] && volume[root] > 0;
        }
}

bool SolidFaces::backOf(const Graph& g, FaceId f, const ViewProjection& view) const {
    return f < solid_.size() && solid_[f] && dot(g.vectorArea(f), view.toward) < 0;
}

namespace {

// An edge's place in the order: its midpoint, or the nearest face it bounds (FaceDepths).
void placeEdge(const Graph& g, EdgeId e, const ViewProjection& view, const SolidFaces& solid, DrawItem& it) {
    const NodeId s = g.source(e), t = g.target(e);
    it.depth = view.depth((g.pos3(s) + g.pos3(t)) / 2.0);
    FaceDepths faces;
    for (CornerId c = g.firstCornerAt(s); c != kNoId; c = g.nextCornerAt(c))
        if (s != t && (g.cornerNode(g.nextCorner(c)) == t || g.cornerNode(g.prevCorner(c)) == t))
            faces.add(g, g.cornerFace(c), view, solid);
    faces.apply(it);
}

}  // namespace

void projectItem(DrawItem& it, const Graph& g, const ViewProjection& view, const SolidFaces& solid) {
    it.inDepth = true;
    if (it.cls == ElemClass::Node) {
        it.a = it.b = view.project(g.pos3(it.id));
        it.depth = view.depth(g.pos3(it.id));
        FaceDepths faces;
        for (CornerId c = g.firstCornerAt(it.id); c != kNoId; c = g.nextCornerAt(c)) faces.add(g, g.cornerFace(c), view, solid);
        faces.apply(it);
        // A node stays on top of its edges (those on its side of a solid): right after the nearest.
        DrawItem edge;
        auto after = [&](EdgeId e) {
            edge.turnedAway = false;
            placeEdge(g, e, view, solid, edge);
            if (edge.turnedAway == it.turnedAway) it.depth = std::min(it.depth, edge.depth);
        };
        for (EdgeId e = g.firstOut(it.id); e != kNoId; e = g.nextOut(e)) after(e);
        for (EdgeId e = g.firstIn(it.id); e != kNoId; e = g.nextIn(e)) after(e);
    } else if (it.cls == ElemClass::Edge) {
        it.a = view.project(g.pos3(g.source(it.id)));
        it.b = view.project(g.pos3(g.target(it.id)));
        placeEdge(g, it.id, view, solid, it);
    } else {
        it.corners.clear();
        CornerId c = g.firstCorner(it.id);
        for (int i = 0; i < g.cornerCount(it.id); ++i, c = g.nextCorner(c)) it.corners.push_back(view.project(g.pos3(g.cornerNode(c))));
        const vec3 centre = g.centroid3(it.id);
        it.a = it.b = view.project(centre);
        it.depth = view.depth(centre);
        it.turnedAway = solid.backOf(g, it.id, view);
    }
}

}  // namespace g2d::rt
