#pragma once
// The plane's orientation and segment tests, in one place for every stage
// that needs them (the drawing step's planarity, G^3's triangulation, the
// SVG examples of `g2d infer`).
#include <algorithm>
#include <cmath>

#include "g2d/vec_math.hpp"

namespace g2d::rt {

// Twice the signed area of a, b, c: > 0 when they turn counter-clockwise.
inline double orient2(vec2 a, vec2 b, vec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// Whether the segments cross at a point inside both: each one's ends lie
// strictly on the two sides of the other's line.
inline bool segmentsCrossProperly(vec2 a, vec2 b, vec2 c, vec2 d) {
    const double o1 = orient2(a, b, c), o2 = orient2(a, b, d), o3 = orient2(c, d, a), o4 = orient2(c, d, b);
    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

// The closed segments meet: they cross, touch, or overlap collinearly.
inline bool segmentsMeet(vec2 a, vec2 b, vec2 c, vec2 d) {
    if (segmentsCrossProperly(a, b, c, d)) return true;
    auto on = [](vec2 p, vec2 q, vec2 r) {   // r, collinear with p and q, on the closed segment
        return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
    };
    return (orient2(c, d, a) == 0 && on(c, d, a)) || (orient2(c, d, b) == 0 && on(c, d, b)) ||
           (orient2(a, b, c) == 0 && on(a, b, c)) || (orient2(a, b, d) == 0 && on(a, b, d));
}

// The squared distance from p to the closed segment a–b.
inline double pointSegmentDistanceSquared(vec2 p, vec2 a, vec2 b) {
    const vec2 ab = b - a, ap = p - a;
    const double len2 = ab.x * ab.x + ab.y * ab.y;
    const double t = len2 > 0 ? std::clamp((ap.x * ab.x + ap.y * ab.y) / len2, 0.0, 1.0) : 0.0;
    const vec2 r = ap - t * ab;
    return r.x * r.x + r.y * r.y;
}

}  // namespace g2d::rt
