// The drawing step's planarity test (drawingIsPlanar, angle_drawing.hpp):
// which edges cross, overlap or pass too close to a vertex. A few tested
// edges are compared with every edge by one linear scan behind a bounding
// box; many (a whole drawing) go through the hash grid the runtime's merging
// uses (spatial_grid.hpp), built for the call.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "g2d/angle_drawing.hpp"
#include "g2d/plane_geometry.hpp"
#include "g2d/spatial_grid.hpp"

namespace g2d::rt {

namespace {

// An item is an edge (a != b) or an isolated vertex (a == b): only a vertex
// without edges needs its own tests, every other one is an end of an edge and
// the edge pair tests measure ends against segments.
struct Item {
    int a, b;
};

struct Box {
    double lox, loy, hix, hiy;
};

bool overlaps(const Box& p, const Box& q) {
    return p.lox <= q.hix && q.lox <= p.hix && p.loy <= q.hiy && q.loy <= p.hiy;
}

Box boxOf(vec2 p, vec2 q, double margin) {
    return {std::min(p.x, q.x) - margin, std::min(p.y, q.y) - margin, std::max(p.x, q.x) + margin,
            std::max(p.y, q.y) + margin};
}

double distance2(vec2 p, vec2 a, vec2 b) { return pointSegmentDistanceSquared(p, a, b); }

class Checker {
public:
    Checker(const std::vector<vec2>& position, const std::vector<Item>& items, double separation)
        : p_(position), items_(items), sep_(separation), sep2_(separation * separation) {}

    // Does the pair conflict? Items are distinct.
    bool conflict(const Item& e, const Item& f) const {
        if (e.a == e.b || f.a == f.b) {
            if (e.a == e.b && f.a == f.b) return near2(p_[e.a], p_[f.a]);
            const Item& pt = e.a == e.b ? e : f;
            const Item& seg = e.a == e.b ? f : e;
            return distance2(p_[pt.a], p_[seg.a], p_[seg.b]) <= sep2_;
        }
        const int shared = (e.a == f.a) + (e.a == f.b) + (e.b == f.a) + (e.b == f.b);
        if (shared >= 2) return true;   // the same two ends: the segments coincide
        if (shared == 1) {
            const int v = (e.a == f.a || e.a == f.b) ? e.a : e.b;
            const int x = e.a == v ? e.b : e.a, y = f.a == v ? f.b : f.a;
            if (distance2(p_[x], p_[f.a], p_[f.b]) <= sep2_ || distance2(p_[y], p_[e.a], p_[e.b]) <= sep2_)
                return true;
            // Same direction from the shared end: they overlap however small the separation.
            const vec2 dx = p_[x] - p_[v], dy = p_[y] - p_[v];
            const double c = dx.x * dy.y - dx.y * dy.x, d = dx.x * dy.x + dx.y * dy.y;
            return d > 0 && std::abs(c) <= 1e-12 * std::sqrt((dx.x * dx.x + dx.y * dx.y) * (dy.x * dy.x + dy.y * dy.y));
        }
        const vec2 a = p_[e.a], b = p_[e.b], c = p_[f.a], d = p_[f.b];
        return segmentsMeet(a, b, c, d) || distance2(a, c, d) <= sep2_ || distance2(b, c, d) <= sep2_ ||
               distance2(c, a, b) <= sep2_ || distance2(d, a, b) <= sep2_;
    }
    // An edge not longer than the separation is a degenerate drawing.
    bool tooShort(const Item& e) const { return e.a != e.b && near2(p_[e.a], p_[e.b]); }

    Box box(int i, double margin) const { return boxOf(p_[items_[i].a], p_[items_[i].b], margin); }
    double separation() const { return sep_; }

private:
    bool near2(vec2 p, vec2 q) const { return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) <= sep2_; }
    const std::vector<vec2>& p_;
    const std::vector<Item>& items_;
    double sep_, sep2_;
};

constexpr std::size_t kScanMax = 32;   // beyond this many tested items, a grid is cheaper than scans

// Each pair is tested once, from its tested item of lower index.
bool pairWanted(int t, int j, const std::vector<char>& tested) { return j != t && (!tested[j] || j > t); }

// `found(t, j)` is told each conflicting pair and returns whether to stop;
// both searches return false when one stopped them.
using FoundConflict = std::function<bool(int, int)>;

bool planarByScan(const Checker& ck, const std::vector<Item>& items, const std::vector<int>& tests,
                  const std::vector<char>& tested, const FoundConflict& found) {
    std::vector<Box> boxes;
    Box all{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int t : tests) {
        boxes.push_back(ck.box(t, ck.separation()));
        all = {std::min(all.lox, boxes.back().lox), std::min(all.loy, boxes.back().loy),
               std::max(all.hix, boxes.back().hix), std::max(all.hiy, boxes.back().hiy)};
    }
    for (int j = 0; j < static_cast<int>(items.size()); ++j) {
        const Box bj = ck.box(j, 0);
        if (!overlaps(all, bj)) continue;
        for (std::size_t k = 0; k < tests.size(); ++k)
            if (pairWanted(tests[k], j, tested) && overlaps(boxes[k], bj) && ck.conflict(items[tests[k]], items[j]) &&
                found(tests[k], j))
                return false;
    }
    return true;
}

bool planarByGrid(const Checker& ck, const std::vector<Item>& items, const std::vector<int>& tests,
                  const std::vector<char>& tested, const FoundConflict& found) {
    const int n = static_cast<int>(items.size());
    std::vector<Box> boxes(items.size());
    Box all{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int i = 0; i < n; ++i) {
        boxes[i] = ck.box(i, 0);
        all = {std::min(all.lox, boxes[i].lox), std::min(all.loy, boxes[i].loy), std::max(all.hix, boxes[i].hix),
               std::max(all.hiy, boxes[i].hiy)};
    }
    // About one cell per item (the grid keeps an item over many cells, a
    // long diagonal edge, in a list every query reads).
    const double span = std::max(all.hix - all.lox, all.hiy - all.loy);
    double cell = span / std::ceil(std::sqrt(static_cast<double>(n)));
    if (!(cell > 0) || !std::isfinite(cell)) cell = 1;
    auto aabb = [](const Box& b) { return Aabb{{b.lox, b.loy, 0}, {b.hix, b.hiy, 0}}; };
    SpatialBoxGrid grid(cell);
    for (int i = 0; i < n; ++i) grid.insert(static_cast<std::uint32_t>(i), aabb(boxes[i]));

    std::vector<std::uint32_t> near;
    for (int t : tests) {
        const Box q = ck.box(t, ck.separation());
        grid.overlapping(aabb(q), near);
        for (std::uint32_t id : near) {
            const int j = static_cast<int>(id);
            if (pairWanted(t, j, tested) && ck.conflict(items[t], items[j]) && found(t, j)) return false;
        }
    }
    return true;
}

}  // namespace

namespace {

// The part's positions and items, then the surroundings near its tested items, fixed.
void addSurroundings(const FixedSurroundings& around, const std::vector<int>& tests, double sep, std::vector<vec2>& position,
                     std::vector<Item>& items) {
    vec2 lo{HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL};
    for (int t : tests)
        for (int v : {items[static_cast<std::size_t>(t)].a, items[static_cast<std::size_t>(t)].b}) {
            lo = {std::min(lo.x, position[static_cast<std::size_t>(v)].x), std::min(lo.y, position[static_cast<std::size_t>(v)].y)};
            hi = {std::max(hi.x, position[static_cast<std::size_t>(v)].x), std::max(hi.y, position[static_cast<std::size_t>(v)].y)};
        }
    std::vector<FixedSegment> found;
    around.near({lo.x - sep, lo.y - sep}, {hi.x + sep, hi.y + sep}, found);
    auto end = [&](int known, vec2 at) {
        if (known >= 0) return known;
        position.push_back(at);
        return static_cast<int>(position.size()) - 1;
    };
    for (const FixedSegment& f : found) {
        const int a = end(f.endA, f.a);
        const int b = f.a == f.b && f.endA == f.endB ? a : end(f.endB, f.b);
        items.push_back({a, b});
    }
}

}  // namespace

bool drawingIsPlanar(const std::vector<vec2>& partPosition, const std::vector<AngleEdge>& edges, double separation,
                     const std::vector<char>& moved, const FixedSurroundings* surroundings) {
    std::vector<vec2> withSurroundings;
    if (surroundings) withSurroundings = partPosition;
    const std::vector<vec2>& position = surroundings ? withSurroundings : partPosition;
    const int nv = static_cast<int>(partPosition.size());
    const double sep = separation > 0 && std::isfinite(separation) ? separation : 0.0;
    for (const vec2& p : position)
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    std::vector<char> hasEdge(position.size(), 0);
    std::vector<Item> items;
    items.reserve(edges.size());
    for (const AngleEdge& e : edges) {
        // A bad index or a loop is no drawing.
        if (e.from < 0 || e.to < 0 || e.from >= nv || e.to >= nv || e.from == e.to) return false;
        hasEdge[e.from] = hasEdge[e.to] = 1;
        items.push_back({e.from, e.to});
    }
    for (int v = 0; v < nv; ++v)
        if (!hasEdge[v]) items.push_back({v, v});

    auto isMoved = [&](int v) { return moved.empty() || (v < static_cast<int>(moved.size()) && moved[v]); };
    std::vector<char> tested(items.size(), 0);
    std::vector<int> tests;
    const Checker ck(position, items, sep);
    for (int i = 0; i < static_cast<int>(items.size()); ++i)
        if (isMoved(items[i].a) || isMoved(items[i].b)) {
            if (ck.tooShort(items[i])) return false;
            tested[i] = 1;
            tests.push_back(i);
        }
    if (tests.empty()) return true;
    if (surroundings) {
        addSurroundings(*surroundings, tests, sep, withSurroundings, items);
        tested.resize(items.size(), 0);
    }
    const FoundConflict stop = [](int, int) { return true; };
    return tests.size() <= kScanMax ? planarByScan(ck, items, tests, tested, stop) : planarByGrid(ck, items, tests, tested, stop);
}

std::vector<std::pair<int, int>> conflictingItems(const std::vector<vec2>& position, const std::vector<std::pair<int, int>>& items,
                                                  double separation) {
    std::vector<std::pair<int, int>> out;
    std::vector<Item> all;
    all.reserve(items.size());
    for (const auto& [a, b] : items) all.push_back({a, b});
    const Checker ck(position, all, separation > 0 && std::isfinite(separation) ? separation : 0.0);
    std::vector<int> tests(all.size());
    for (std::size_t i = 0; i < all.size(); ++i) tests[i] = static_cast<int>(i);
    const std::vector<char> tested(all.size(), 1);
    const FoundConflict collect = [&](int t, int j) {
        out.emplace_back(std::min(t, j), std::max(t, j));
        return false;
    };
    if (tests.size() <= kScanMax) planarByScan(ck, all, tests, tested, collect);
    else planarByGrid(ck, all, tests, tested, collect);
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace g2d::rt
