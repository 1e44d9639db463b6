// Faces of a planar straight-line drawing whose edges name the face kinds on
// their sides (angle_faces.hpp): half-edges sorted round each vertex, one
// walk per cycle, each walk cut into simple cycles at repeated vertices;
// the clockwise ones inside a face are its holes (ring_nesting.hpp).
#include "g2d/angle_faces.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "g2d/ring_nesting.hpp"

namespace g2d::rt {

namespace {

bool finite(vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Half-edge h is edge h / 2, from->to when h is even; its twin is h ^ 1.
struct HalfEdges {
    std::vector<char> valid;   // per half-edge: its edge is usable
    std::vector<int> origin, target, kind;   // kind: the face kind on its left
    std::vector<int> begin;    // per vertex: where its half-edges start in `around` (size V + 1)
    std::vector<int> around;   // half-edges grouped by origin, counter-clockwise by angle
    std::vector<int> rank;     // per half-edge: its index among its origin's
};

HalfEdges build(const std::vector<vec2>& position, const std::vector<SidedEdge>& edges) {
    const int vertices = static_cast<int>(position.size());
    const int halves = 2 * static_cast<int>(edges.size());
    HalfEdges g;
    g.valid.assign(halves, 0);
    g.origin.assign(halves, -1);
    g.target.assign(halves, -1);
    g.kind.assign(halves, -1);
    g.rank.assign(halves, -1);
    g.begin.assign(vertices + 1, 0);
    auto usable = [&](int v) { return v >= 0 && v < vertices && finite(position[v]); };
    for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
        const SidedEdge& s = edges[e];
        if (!usable(s.from) || !usable(s.to) || s.from == s.to) continue;
        for (int h : {2 * e, 2 * e + 1}) {
            const bool forward = h == 2 * e;
            g.valid[h] = 1;
            g.origin[h] = forward ? s.from : s.to;
            g.target[h] = forward ? s.to : s.from;
            g.kind[h] = forward ? s.left : s.right;
            ++g.begin[g.origin[h] + 1];
        }
    }
    for (int v = 0; v < vertices; ++v) g.begin[v + 1] += g.begin[v];
    g.around.assign(g.begin[vertices], -1);
    std::vector<int> fill(g.begin.begin(), g.begin.end() - 1);
    std::vector<double> angle(halves, 0);
    for (int h = 0; h < halves; ++h) {
        if (!g.valid[h]) continue;
        const vec2 d = position[g.target[h]] - position[g.origin[h]];
        angle[h] = std::atan2(d.y, d.x);
        g.around[fill[g.origin[h]]++] = h;
    }
    // Ties (only in a non-planar drawing) fall back to the half-edge index,
    // so the order stays deterministic.
    for (int v = 0; v < vertices; ++v) {
        const auto first = g.around.begin() + g.begin[v], last = g.around.begin() + g.begin[v + 1];
        std::sort(first, last, [&](int a, int b) { return std::pair(angle[a], a) < std::pair(angle[b], b); });
        for (int i = g.begin[v]; i < g.begin[v + 1]; ++i) g.rank[g.around[i]] = i - g.begin[v];
    }
    return g;
}

// After u->v: the half-edge just clockwise of v->u round v (the face on the
// left turns as far right as it can). A permutation of the half-edges.
int next(const HalfEdges& g, int h) {
    const int twin = h ^ 1, v = g.origin[twin];
    const int count = g.begin[v + 1] - g.begin[v];
    return g.around[g.begin[v] + (g.rank[twin] + count - 1) % count];
}

// The kind most of `cycle` has; ties go to the smallest.
int vote(const HalfEdges& g, const std::vector<int>& cycle) {
    std::vector<int> kinds;
    for (int h : cycle) kinds.push_back(g.kind[h]);
    std::sort(kinds.begin(), kinds.end());
    int best = -1, bestCount = 0;
    for (size_t i = 0; i < kinds.size();) {
        size_t j = i;
        while (j < kinds.size() && kinds[j] == kinds[i]) ++j;
        if (static_cast<int>(j - i) > bestCount) best = kinds[i], bestCount = static_cast<int>(j - i);
        i = j;
    }
    return best;
}

// A simple cycle (distinct origins) of the walks, by its least half-edge.
struct Cycle {
    std::vector<int> halves;   // from the least half-edge
    Ring ring;                 // its origins and signed area
    int kind = -1;
};

void record(const HalfEdges& g, const std::vector<vec2>& position, std::vector<int> halves, std::vector<Cycle>& cycles) {
    if (halves.size() < 3) return;   // a spike u->v->u
    Cycle c;
    c.kind = vote(g, halves);
    // Shoelace about the first corner: less cancellation far from the origin.
    const vec2 p0 = position[g.origin[halves[0]]];
    for (int h : halves) {
        const vec2 a = position[g.origin[h]] - p0, b = position[g.target[h]] - p0;
        c.ring.area += a.x * b.y - a.y * b.x;
    }
    std::rotate(halves.begin(), std::min_element(halves.begin(), halves.end()), halves.end());
    for (int h : halves) c.ring.corners.push_back(g.origin[h]);
    c.halves = std::move(halves);
    cycles.push_back(std::move(c));
}

// Bounded faces: counter-clockwise cycles with a kind, each with the
// clockwise cycles it is the innermost around (its holes).
std::vector<TracedFace> facesOf(const std::vector<vec2>& position, std::vector<Cycle> cycles) {
    std::sort(cycles.begin(), cycles.end(), [](const Cycle& a, const Cycle& b) { return a.halves[0] < b.halves[0]; });
    std::vector<Ring> rings;
    for (const Cycle& c : cycles) rings.push_back(c.ring);
    const std::vector<int> around = enclosingRings(position, rings);
    std::vector<int> faceOf(cycles.size(), -1);
    std::vector<TracedFace> faces;
    for (std::size_t i = 0; i < cycles.size(); ++i) {
        if (!(cycles[i].ring.area > 0) || cycles[i].kind < 0) continue;
        faceOf[i] = static_cast<int>(faces.size());
        faces.push_back(TracedFace{cycles[i].kind, std::move(cycles[i].ring.corners), {}});
    }
    for (std::size_t i = 0; i < cycles.size(); ++i)
        if (around[i] >= 0 && faceOf[static_cast<std::size_t>(around[i])] >= 0)
            faces[static_cast<std::size_t>(faceOf[static_cast<std::size_t>(around[i])])].holes.push_back(std::move(cycles[i].ring.corners));
    return faces;
}

}  // namespace

std::vector<TracedFace> traceFaces(const std::vector<vec2>& position, const std::vector<SidedEdge>& edges) {
    const HalfEdges g = build(position, edges);
    const int halves = static_cast<int>(g.valid.size());
    std::vector<Cycle> cycles;
    std::vector<char> seen(halves, 0);
    // The walk so far: walkHalf[k] leaves walkVertex[k]; at[v] is v's index
    // in walkVertex, -1 when v is not on it. A half-edge reaching a vertex
    // on the walk closes a simple cycle, which is cut out.
    std::vector<int> at(position.size(), -1), walkVertex, walkHalf;
    for (int start = 0; start < halves; ++start) {
        if (!g.valid[start] || seen[start]) continue;
        walkVertex.assign(1, g.origin[start]);
        walkHalf.clear();
        at[g.origin[start]] = 0;
        int h = start;
        do {
            seen[h] = 1;
            walkHalf.push_back(h);
            const int v = g.target[h];
            if (const int i = at[v]; i >= 0) {
                record(g, position, std::vector<int>(walkHalf.begin() + i, walkHalf.end()), cycles);
                for (size_t k = i + 1; k < walkVertex.size(); ++k) at[walkVertex[k]] = -1;
                walkVertex.resize(i + 1);
                walkHalf.resize(i);
            } else {
                at[v] = static_cast<int>(walkVertex.size());
                walkVertex.push_back(v);
            }
            h = next(g, h);
        } while (h != start);
        at[g.origin[start]] = -1;   // the walk ends where it began: only that vertex is left on it
    }
    return facesOf(position, std::move(cycles));
}

}  // namespace g2d::rt
