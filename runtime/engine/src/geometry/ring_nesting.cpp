#include "g2d/ring_nesting.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace g2d::rt {

namespace {

struct Box {
    vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
    bool holds(const Box& o) const { return lo.x <= o.lo.x && lo.y <= o.lo.y && o.hi.x <= hi.x && o.hi.y <= hi.y; }
};

Box boxOf(const std::vector<vec2>& position, const Ring& r) {
    Box b;
    for (int v : r.corners) {
        const vec2 p = position[static_cast<std::size_t>(v)];
        b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y)};
        b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y)};
    }
    return b;
}

// Crossing number of a ray to +x; p lies on no side (a plane drawing).
bool inside(const std::vector<vec2>& position, const Ring& r, vec2 p) {
    bool in = false;
    const std::size_t n = r.corners.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const vec2 a = position[static_cast<std::size_t>(r.corners[i])], b = position[static_cast<std::size_t>(r.corners[j])];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
    return in;
}

}  // namespace

std::vector<int> enclosingRings(const std::vector<vec2>& position, const std::vector<Ring>& rings) {
    std::vector<int> out(rings.size(), -1);
    std::vector<Box> box;
    for (const Ring& r : rings) box.push_back(boxOf(position, r));
    std::vector<std::size_t> onRing(position.size(), rings.size());   // the ring whose corners are marked
    for (std::size_t h = 0; h < rings.size(); ++h) {
        if (!(rings[h].area < 0)) continue;
        double best = INFINITY;
        for (std::size_t r = 0; r < rings.size(); ++r) {
            const Ring& around = rings[r];
            if (!(around.area > -rings[h].area) || around.area >= best || !box[r].holds(box[h])) continue;
            for (int v : around.corners) onRing[static_cast<std::size_t>(v)] = r;
            // A corner of the hole off the ring: its side is the whole hole's.
            const auto off = std::find_if(rings[h].corners.begin(), rings[h].corners.end(),
                                          [&](int v) { return onRing[static_cast<std::size_t>(v)] != r; });
            if (off == rings[h].corners.end() || !inside(position, around, position[static_cast<std::size_t>(*off)])) continue;
            best = around.area;
            out[h] = static_cast<int>(r);
        }
    }
    return out;
}

}  // namespace g2d::rt
