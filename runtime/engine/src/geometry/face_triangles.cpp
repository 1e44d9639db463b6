#include "g2d/face_triangles.hpp"

#include <algorithm>
#include <cmath>

#include "g2d/plane_geometry.hpp"
#include "g2d/polygon_triangles.hpp"

namespace g2d::rt {

namespace {

std::vector<NodeId> outerRing(const Graph& g, FaceId f) {
    std::vector<NodeId> ring;
    CornerId c = g.firstCorner(f);
    for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) ring.push_back(g.cornerNode(c));
    return ring;
}

vec3 newellSum(const std::vector<vec3>& p, std::size_t begin, std::size_t end) {
    vec3 n(0.0);
    for (std::size_t i = begin; i < end; ++i) {
        const vec3 a = p[i], b = p[i + 1 < end ? i + 1 : begin];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

// The plane coordinates along `n`: the axis of its largest component is
// dropped, the other two taken in the order that keeps a ring running
// counter-clockwise about `n` counter-clockwise in the plane.
vec2 project(vec3 p, vec3 n) {
    const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
    if (az >= ax && az >= ay) return n.z >= 0 ? vec2(p.x, p.y) : vec2(p.y, p.x);
    if (ax >= ay) return n.x >= 0 ? vec2(p.y, p.z) : vec2(p.z, p.y);
    return n.y >= 0 ? vec2(p.z, p.x) : vec2(p.x, p.z);
}

double signedArea(const std::vector<vec2>& p, const std::vector<int>& ring) {
    double twice = 0;
    for (std::size_t i = 0; i < ring.size(); ++i)
        twice += cross(p[static_cast<std::size_t>(ring[i])], p[static_cast<std::size_t>(ring[(i + 1) % ring.size()])]);
    return twice / 2;
}

// Whether some two sides of the rings that do not follow each other cross
// or touch; O(n^2), faces have few sides.
bool sidesCross(const std::vector<vec2>& p, const std::vector<std::vector<int>>& rings) {
    struct Side { vec2 a, b; };
    std::vector<Side> sides;
    for (const auto& ring : rings)
        for (std::size_t i = 0; i < ring.size(); ++i)
            sides.push_back({p[static_cast<std::size_t>(ring[i])], p[static_cast<std::size_t>(ring[(i + 1) % ring.size()])]});
    auto shares = [](const Side& s, const Side& t) { return s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b; };
    for (std::size_t i = 0; i < sides.size(); ++i)
        for (std::size_t j = i + 1; j < sides.size(); ++j) {
            const Side &s = sides[i], &t = sides[j];
            if (shares(s, t)) continue;   // neighbours, or rings touching at a corner
            const double d1 = orient2(s.a, s.b, t.a), d2 = orient2(s.a, s.b, t.b);
            const double d3 = orient2(t.a, t.b, s.a), d4 = orient2(t.a, t.b, s.b);
            if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
        }
    return false;
}

}  // namespace

FaceTriangles triangulateFace(const Graph& g, FaceId f) {
    FaceTriangles out;
    std::vector<std::vector<int>> rings;   // outer first, by point index
    auto addRing = [&](const std::vector<NodeId>& nodes) {
        auto& ring = rings.emplace_back();
        forEachRingPoint(g, nodes, [&](const PathPoint& p) {
            out.points.push_back(p);
            if (p.node != kNoId) {
                out.positions.push_back(g.pos3(p.node));
            } else {
                const vec2 b = g.edgeBend(p.edge)[p.index];
                out.positions.push_back(vec3(b.x, b.y, 0.0));
            }
            ring.push_back(static_cast<int>(out.points.size()) - 1);
        });
    };
    addRing(outerRing(g, f));
    for (const std::vector<NodeId>& hole : g.faceHoles(f)) addRing(hole);

    const std::size_t outerEnd = rings[0].size();
    const vec3 sum = newellSum(out.positions, 0, outerEnd);
    double size = 0;
    for (std::size_t i = 1; i < outerEnd; ++i) size = std::max(size, length(out.positions[i] - out.positions[0]));
    const double twiceArea = length(sum);   // projected along its normal
    if (size == 0 || twiceArea <= 1e-12 * size * size) {
        // No area: a line of corners, or a figure eight whose lobes cancel
        // (its plane unknown, so seen along each axis: a line never crosses).
        out.problem = FaceShapeProblem::Collinear;
        for (const vec3 axis : {vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1)}) {
            std::vector<vec2> flat;
            for (const vec3& p : out.positions) flat.push_back(project(p, axis));
            if (size > 0 && sidesCross(flat, rings)) out.problem = FaceShapeProblem::SelfCrossing;
        }
        return out;
    }
    out.normal = sum / twiceArea;

    std::vector<vec2> flat;
    flat.reserve(out.positions.size());
    for (const vec3& p : out.positions) flat.push_back(project(p, out.normal));
    std::vector<std::vector<int>> holes(rings.begin() + 1, rings.end());
    for (auto& hole : holes)
        if (signedArea(flat, hole) > 0) std::reverse(hole.begin(), hole.end());   // holes run clockwise
    if (sidesCross(flat, rings)) {
        out.problem = FaceShapeProblem::SelfCrossing;
        return out;
    }
    double area = signedArea(flat, rings[0]), covered = 0;
    for (const auto& hole : holes) area += signedArea(flat, hole);
    for (const auto& t : triangulate(flat, rings[0], holes)) {
        out.triangles.push_back({static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]), static_cast<std::uint32_t>(t[2])});
        const auto at = [&](int i) { return flat[static_cast<std::size_t>(i)]; };
        covered += orient2(at(t[0]), at(t[1]), at(t[2])) / 2;
    }
    // Rings that overlap without crossing (a hole outside its face) leave
    // part uncovered; the triangles must account for the whole area.
    if (std::abs(covered - area) > 1e-9 * std::max(std::abs(area), size * size)) out.problem = FaceShapeProblem::SelfCrossing;
    return out;
}

std::string faceShapeMessage(const Graph& g, FaceId f, const std::string& kindName, FaceShapeProblem problem) {
    std::string text = "face " + std::to_string(f) + " (" + kindName + ", corners";
    for (NodeId n : outerRing(g, f)) text += " " + std::to_string(n);
    text += ") cannot be drawn as triangles: ";
    text += problem == FaceShapeProblem::Collinear ? "its corners lie on one line, so it has no area"
                                                   : "its outline crosses itself";
    return text;
}

}  // namespace g2d::rt
