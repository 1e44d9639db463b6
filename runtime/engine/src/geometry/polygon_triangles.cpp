#include "g2d/polygon_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "g2d/plane_geometry.hpp"

namespace g2d::rt {

namespace {

bool same(vec2 a, vec2 b) { return a.x == b.x && a.y == b.y; }

// p in triangle abc or on its sides, whichever way round it runs.
bool inTriangle(vec2 a, vec2 b, vec2 c, vec2 p) {
    const double d1 = orient2(a, b, p), d2 = orient2(b, c, p), d3 = orient2(c, a, p);
    return !((d1 < 0 || d2 < 0 || d3 < 0) && (d1 > 0 || d2 > 0 || d3 > 0));
}

// One polygon as a doubly linked ring of nodes, each a corner (index into
// the points); a corner may have two nodes (the ends of a bridge).
class Polygon {
public:
    explicit Polygon(const std::vector<vec2>& points) : points_(points) {}

    int ring(const std::vector<int>& corners) {
        int first = -1, last = -1;
        for (int c : corners) {
            last = add(c, last);
            if (first < 0) first = last;
        }
        return first;
    }

    // Joins the hole (a clockwise ring) to the ring through `start`: from
    // the hole's rightmost corner M a bridge to a corner P it sees, walked
    // both ways (P, M, the hole, M, P).
    void bridge(int start, const std::vector<int>& hole) {
        const auto m = static_cast<std::size_t>(
            std::max_element(hole.begin(), hole.end(), [&](int a, int b) { return at(a).x < at(b).x; }) - hole.begin());
        const int p = visibleFrom(start, at(hole[m]));
        if (p < 0) return;   // not inside: left out rather than a wrong cover
        int last = p;
        for (std::size_t k = 0; k <= hole.size(); ++k) last = add(hole[(m + k) % hole.size()], last);
        add(index_[static_cast<std::size_t>(p)], last);
    }

    // Cuts off ears (a convex corner whose triangle holds no other corner)
    // until two corners are left; a pass without an ear drops a corner that
    // adds no area (collinear, or a bridge's doubled end).
    void clip(int ear, std::vector<std::array<int, 3>>& out) {
        std::size_t count = 0;
        for (int n = ear; count == 0 || n != ear; n = next_[static_cast<std::size_t>(n)]) ++count;
        for (int stop = ear; count > 2;) {
            const int a = prev(ear), c = next(ear);
            if (isEar(ear)) {
                out.push_back({index_[static_cast<std::size_t>(a)], index_[static_cast<std::size_t>(ear)], index_[static_cast<std::size_t>(c)]});
                remove(ear);
                --count;
                ear = stop = c;
                continue;
            }
            ear = c;
            if (ear != stop) continue;
            const int flat = findFlat(ear);
            if (flat < 0) return;   // not a simple polygon: the rest stays uncovered
            ear = stop = next(flat);
            remove(flat);
            --count;
        }
    }

private:
    int add(int corner, int after) {
        const int n = static_cast<int>(index_.size());
        index_.push_back(corner);
        if (after < 0) {
            prev_.push_back(n);
            next_.push_back(n);
        } else {
            const int after2 = next(after);
            prev_.push_back(after);
            next_.push_back(after2);
            next_[static_cast<std::size_t>(after)] = n;
            prev_[static_cast<std::size_t>(after2)] = n;
        }
        return n;
    }
    void remove(int n) {
        next_[static_cast<std::size_t>(prev(n))] = next(n);
        prev_[static_cast<std::size_t>(next(n))] = prev(n);
    }
    int prev(int n) const { return prev_[static_cast<std::size_t>(n)]; }
    int next(int n) const { return next_[static_cast<std::size_t>(n)]; }
    vec2 at(int corner) const { return points_[static_cast<std::size_t>(corner)]; }
    vec2 pos(int n) const { return at(index_[static_cast<std::size_t>(n)]); }

    // The node a bridge from m may end at, or -1.
    int visibleFrom(int start, vec2 m) const { return facing(start, seenCorner(start, m), m); }

    // Eberly's visible corner: the ray from m to +x meets the ring first on
    // a side at I; that side's right end P sees m unless a reflex corner lies
    // in the triangle m, I, P, and then the one at the least angle to the ray
    // does. A corner at m itself (a hole touching the ring) is its own bridge.
    int seenCorner(int start, vec2 m) const {
        double hitX = INFINITY;
        int hit = -1;
        bool onCorner = false;   // the ray meets corner `hit` first (axis-aligned drawings often do)
        int n = start;
        do {
            const vec2 a = pos(n), b = pos(next(n));
            if (same(a, m)) return n;
            if (a.y == m.y && a.x > m.x && a.x < hitX) {
                hitX = a.x, hit = n, onCorner = true;
            } else if ((a.y > m.y) != (b.y > m.y)) {
                const double x = a.x + (m.y - a.y) * (b.x - a.x) / (b.y - a.y);
                if (x >= m.x && x < hitX) hitX = x, hit = n, onCorner = false;
            }
            n = next(n);
        } while (n != start);
        if (hit < 0) return -1;
        if (onCorner) return hit;
        const vec2 I{hitX, m.y};
        if (same(pos(hit), I)) return hit;   // the ray meets a corner
        if (same(pos(next(hit)), I)) return next(hit);
        int best = pos(hit).x > pos(next(hit)).x ? hit : next(hit);
        const vec2 P = pos(best);
        double bestTan = INFINITY;
        n = start;
        do {
            const vec2 r = pos(n);
            if (n != best && r.x > m.x && orient2(pos(prev(n)), r, pos(next(n))) < 0 && inTriangle(m, I, P, r)) {
                const double t = std::abs(r.y - m.y) / (r.x - m.x);
                if (t < bestTan || (t == bestTan && r.x < pos(best).x)) bestTan = t, best = n;
            }
            n = next(n);
        } while (n != start);
        return best;
    }

    // Of the nodes at p's place (a corner a bridge passes twice), the one
    // whose inside wedge m lies in: bridging from the other would join the
    // hole on the wrong side of that bridge.
    int facing(int start, int p, vec2 m) const {
        if (p < 0) return p;
        int n = start;
        do {
            if (same(pos(n), pos(p))) {
                const vec2 a = pos(prev(n)), b = pos(n), c = pos(next(n));
                const bool convex = orient2(a, b, c) > 0;
                const bool left1 = orient2(a, b, m) >= 0, left2 = orient2(b, c, m) >= 0;
                if (convex ? left1 && left2 : left1 || left2) return n;
            }
            n = next(n);
        } while (n != start);
        return p;
    }

    bool isEar(int b) const {
        const int a = prev(b), c = next(b);
        const vec2 A = pos(a), B = pos(b), C = pos(c);
        if (!(orient2(A, B, C) > 0)) return false;
        for (int p = next(c); p != a; p = next(p)) {
            const vec2 P = pos(p);
            if (!same(P, A) && !same(P, B) && !same(P, C) && inTriangle(A, B, C, P)) return false;
        }
        return true;
    }

    // The corner that turns least (the sine of its turn below 1e-9: rounding
    // can leave collinear corners a hair off), or -1.
    int findFlat(int start) const {
        int n = start, flattest = -1;
        double least = 1e-9;
        do {
            const vec2 a = pos(prev(n)), b = pos(n), c = pos(next(n));
            const double lengths = std::hypot(b.x - a.x, b.y - a.y) * std::hypot(c.x - b.x, c.y - b.y);
            const double turn = lengths > 0 ? std::abs(orient2(a, b, c)) / lengths : 0;
            if (turn <= least) least = turn, flattest = n;
            n = next(n);
        } while (n != start && least > 0);
        return flattest;
    }

    const std::vector<vec2>& points_;
    std::vector<int> index_, prev_, next_;
};

}  // namespace

std::vector<std::array<int, 3>> triangulate(const std::vector<vec2>& points, const std::vector<int>& outer,
                                            const std::vector<std::vector<int>>& holes) {
    std::vector<std::array<int, 3>> out;
    if (outer.size() < 3) return out;
    Polygon polygon(points);
    const int start = polygon.ring(outer);
    // Rightmost holes first, so that a later hole's bridge may end on an earlier one.
    std::vector<const std::vector<int>*> order;
    for (const auto& h : holes)
        if (h.size() >= 3) order.push_back(&h);
    auto right = [&](const std::vector<int>* h) {
        double x = -INFINITY;
        for (int c : *h) x = std::max(x, points[static_cast<std::size_t>(c)].x);
        return x;
    };
    std::stable_sort(order.begin(), order.end(), [&](const auto* a, const auto* b) { return right(a) > right(b); });
    for (const auto* h : order) polygon.bridge(start, *h);
    polygon.clip(start, out);
    return out;
}

}  // namespace g2d::rt
