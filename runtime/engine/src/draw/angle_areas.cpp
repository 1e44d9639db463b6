#include <algorithm>
#include <cmath>
#include <numeric>

#include "g2d/angle_drawing.hpp"

namespace g2d::rt {

namespace {

int root(std::vector<int>& parent, int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

struct Box {
    vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
    void add(vec2 p) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    bool meets(const Box& o) const { return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y; }
};

// The area of the wedge at `v` that contains the direction straight down:
// left of the edge from which a counter-clockwise turn reaches that direction soonest.
int areaBelow(int v, const std::vector<vec2>& pos, const std::vector<AngleEdge>& edges, const std::vector<int>& at) {
    constexpr double kDown = -M_PI / 2;
    int best = -1;
    double bestTurn = 0;
    for (int e : at) {
        const AngleEdge& ed = edges[static_cast<std::size_t>(e)];
        const bool out = ed.from == v;
        const vec2 d = pos[static_cast<std::size_t>(out ? ed.to : ed.from)] - pos[static_cast<std::size_t>(v)];
        // The counter-clockwise turn from this edge to straight down, in (0, 2π].
        double turn = std::fmod(kDown - std::atan2(d.y, d.x) + 4 * M_PI, 2 * M_PI);
        if (turn <= 0) turn += 2 * M_PI;
        if (best < 0 || turn < bestTurn) best = e, bestTurn = turn;
    }
    const AngleEdge& ed = edges[static_cast<std::size_t>(best)];
    return ed.from == v ? ed.left : ed.right;   // counter-clockwise from it lies its left side (leaving v)
}

}  // namespace

bool areasConsistent(const std::vector<vec2>& pos, const std::vector<AngleEdge>& edges, const std::vector<char>& moved) {
    const int nv = static_cast<int>(pos.size());
    std::vector<int> parent(static_cast<std::size_t>(nv));
    std::iota(parent.begin(), parent.end(), 0);
    std::vector<std::vector<int>> at(static_cast<std::size_t>(nv));
    for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
        const AngleEdge& ed = edges[static_cast<std::size_t>(e)];
        if (ed.from < 0 || ed.to < 0 || ed.from >= nv || ed.to >= nv || ed.from == ed.to) continue;
        at[static_cast<std::size_t>(ed.from)].push_back(e);
        at[static_cast<std::size_t>(ed.to)].push_back(e);
        parent[static_cast<std::size_t>(root(parent, ed.from))] = root(parent, ed.to);
    }
    // Per component (by root): its box, its lowest vertex, whether it moved.
    std::vector<Box> box(static_cast<std::size_t>(nv));
    std::vector<int> lowest(static_cast<std::size_t>(nv), -1);
    std::vector<char> touched(static_cast<std::size_t>(nv), 0);
    for (int v = 0; v < nv; ++v) {
        if (at[static_cast<std::size_t>(v)].empty()) continue;
        const auto r = static_cast<std::size_t>(root(parent, v));
        const vec2 p = pos[static_cast<std::size_t>(v)];
        box[r].add(p);
        const int l = lowest[r];
        if (l < 0 || p.y < pos[static_cast<std::size_t>(l)].y || (p.y == pos[static_cast<std::size_t>(l)].y && p.x < pos[static_cast<std::size_t>(l)].x))
            lowest[r] = v;
        if (static_cast<std::size_t>(v) < moved.size() && moved[static_cast<std::size_t>(v)]) touched[r] = 1;
    }
    std::vector<int> roots;
    for (int v = 0; v < nv; ++v)
        if (lowest[static_cast<std::size_t>(v)] >= 0) roots.push_back(v);
    for (int c : roots) {
        bool test = touched[static_cast<std::size_t>(c)] != 0;
        for (int t : roots)
            test = test || (touched[static_cast<std::size_t>(t)] && box[static_cast<std::size_t>(t)].meets(box[static_cast<std::size_t>(c)]));
        if (!test) continue;
        const int v = lowest[static_cast<std::size_t>(c)];
        const vec2 p = pos[static_cast<std::size_t>(v)];
        // The first edge of another component straight below p.
        int below = -1;
        double belowY = -1e300;
        for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
            const AngleEdge& ed = edges[static_cast<std::size_t>(e)];
            if (ed.from < 0 || ed.to < 0 || ed.from >= nv || ed.to >= nv || ed.from == ed.to || root(parent, ed.from) == c) continue;
            const vec2 a = pos[static_cast<std::size_t>(ed.from)], b = pos[static_cast<std::size_t>(ed.to)];
            // Half-open in x, so a ray through a vertex meets one of its two edges.
            if (a.x == b.x || p.x < std::min(a.x, b.x) || p.x >= std::max(a.x, b.x)) continue;
            const double y = a.y + (b.y - a.y) * (p.x - a.x) / (b.x - a.x);
            if (y < p.y && y > belowY) below = e, belowY = y;
        }
        int outside = -1;
        if (below >= 0) {
            const AngleEdge& ed = edges[static_cast<std::size_t>(below)];
            outside = pos[static_cast<std::size_t>(ed.to)].x > pos[static_cast<std::size_t>(ed.from)].x ? ed.left : ed.right;
        }
        if (areaBelow(v, pos, edges, at[static_cast<std::size_t>(v)]) != outside) return false;
    }
    return true;
}

}  // namespace g2d::rt
