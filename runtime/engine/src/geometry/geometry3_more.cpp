// Thick edges against faces, and the plane's outline tests (geometry3.hpp,
// docs/language.md §16.8).
#include "g2d/geometry3.hpp"
#include "g2d/plane_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

namespace g2d::rt {
namespace {

constexpr double kRelEps = 1e-9;

double sizeOf(std::span<const vec3> points, std::initializer_list<vec3> more) {
    const vec3 first = points.empty() ? *more.begin() : points[0];
    double size = 0;
    auto grow = [&](vec3 p) { size = std::max({size, std::abs(p.x - first.x), std::abs(p.y - first.y), std::abs(p.z - first.z)}); };
    for (const vec3& p : points) grow(p);
    for (const vec3& p : more) grow(p);
    return size;
}

double pointSegmentDistance3(vec3 p, vec3 a, vec3 b) {
    const vec3 d = b - a;
    const double l2 = glm::dot(d, d);
    const double t = l2 > 0 ? std::clamp(glm::dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * d));
}

// The distance from p to the closed triangle (Ericson's closest point, by
// regions); a degenerate triangle is its sides.
double pointTriangleDistance(vec3 p, vec3 a, vec3 b, vec3 c) {
    const vec3 n = glm::cross(b - a, c - a);
    const double nl = glm::length(n);
    const double sides = std::min({pointSegmentDistance3(p, a, b), pointSegmentDistance3(p, b, c), pointSegmentDistance3(p, c, a)});
    const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    if (nl <= kRelEps * longest * longest) return sides;
    // Inside the prism over the triangle: the height; outside it the nearest side.
    const vec3 nh = n / nl;
    const double h = glm::dot(p - a, nh);
    const vec3 q = p - h * nh;
    const bool inside = glm::dot(glm::cross(b - a, q - a), n) >= 0 && glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
                        glm::dot(glm::cross(a - c, q - c), n) >= 0;
    return inside ? std::abs(h) : sides;
}

// Where the closed segment crosses the closed triangle's plane inside it.
bool segmentHitsTriangle(vec3 o0, vec3 o1, vec3 a, vec3 b, vec3 c) {
    const vec3 n = glm::cross(b - a, c - a);
    const double d0 = glm::dot(o0 - a, n), d1 = glm::dot(o1 - a, n);
    if ((d0 > 0 && d1 > 0) || (d0 < 0 && d1 < 0) || d0 == d1) return false;   // one side, or in the plane (the sides decide)
    const vec3 q = o0 + (d0 / (d0 - d1)) * (o1 - o0);
    return glm::dot(glm::cross(b - a, q - a), n) >= 0 && glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
           glm::dot(glm::cross(a - c, q - c), n) >= 0;
}

// --- the plane ---

vec2 flat(vec3 p) { return {p.x, p.y}; }

// -1 strictly outside, 0 on the outline (within eps), 1 strictly inside.
int classify(vec2 p, std::span<const vec3> polygon, double eps) {
    const std::size_t n = polygon.size();
    bool inside = false;
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const vec2 a = flat(polygon[i]), b = flat(polygon[j]);
        if (pointSegmentDistanceSquared(p, a, b) <= eps * eps) return 0;
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    }
    return inside ? 1 : -1;
}

// The parameter of p's projection on a→b (p near the segment's line).
double along(vec2 a, vec2 b, vec2 p) {
    const vec2 d = b - a;
    const double l2 = d.x * d.x + d.y * d.y;
    return l2 > 0 ? ((p.x - a.x) * d.x + (p.y - a.y) * d.y) / l2 : 0;
}

}  // namespace

double segmentTriangleDistance(vec3 o0, vec3 o1, vec3 p0, vec3 p1, vec3 p2) {
    if (segmentHitsTriangle(o0, o1, p0, p1, p2)) return 0;
    return std::min({pointTriangleDistance(o0, p0, p1, p2), pointTriangleDistance(o1, p0, p1, p2), segmentDistance(o0, o1, p0, p1),
                     segmentDistance(o0, o1, p1, p2), segmentDistance(o0, o1, p2, p0)});
}

bool thickSegmentPolygon(vec3 o0, vec3 o1, double radius, int shared, std::span<const vec3> polygon) {
    if (segmentPolygon(o0, o1, polygon)) return true;
    if (!(radius > 0) || polygon.size() < 3) return false;
    const double eps = kRelEps * sizeOf(polygon, {o0, o1});
    const auto at = [&](int i) { return polygon[static_cast<std::size_t>(i)]; };
    const vec3 far = shared == 0 ? o1 : o0;
    double least = std::numeric_limits<double>::infinity();
    for (const auto& t : triangulate(polygon))
        least = std::min(least, shared >= 0 ? pointTriangleDistance(far, at(t[0]), at(t[1]), at(t[2]))
                                            : segmentTriangleDistance(o0, o1, at(t[0]), at(t[1]), at(t[2])));
    return least <= radius + eps;
}

bool segmentCrossesOutline(vec3 o0, vec3 o1, std::span<const vec3> polygon) {
    if (polygon.size() < 3) return false;
    const double eps = kRelEps * sizeOf(polygon, {o0, o1});
    const vec2 a = flat(o0), b = flat(o1);
    const vec2 d = b - a;
    if (d.x * d.x + d.y * d.y <= eps * eps) return false;
    // Cut the segment where it meets the outline; each piece is then wholly
    // inside, outside or on the outline, told by its midpoint.
    std::vector<double> cuts{0.0, 1.0};
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const vec2 p = flat(polygon[i]), q = flat(polygon[(i + 1) % n]);
        if (segmentsCrossProperly(a, b, p, q)) {
            const double o1 = orient2(p, q, a), o2 = orient2(p, q, b);
            cuts.push_back(o1 / (o1 - o2));
        }
        for (const vec2 v : {p, q})   // a corner on the segment (a touch, or a collinear overlap's end)
            if (pointSegmentDistanceSquared(v, a, b) <= eps * eps) cuts.push_back(along(a, b, v));
    }
    std::sort(cuts.begin(), cuts.end());
    const double tiny = eps / std::sqrt(d.x * d.x + d.y * d.y);
    bool in = false, out = false;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double lo = std::clamp(cuts[i], 0.0, 1.0), hi = std::clamp(cuts[i + 1], 0.0, 1.0);
        if (hi - lo <= tiny) continue;
        const int where = classify(a + ((lo + hi) / 2) * d, polygon, eps);
        in = in || where > 0;
        out = out || where < 0;
    }
    return in && out;
}

bool outlinesCross(std::span<const vec3> p, std::span<const vec3> q) {
    for (std::size_t i = 0; i < p.size(); ++i)
        if (segmentCrossesOutline(p[i], p[(i + 1) % p.size()], q)) return true;
    for (std::size_t i = 0; i < q.size(); ++i)
        if (segmentCrossesOutline(q[i], q[(i + 1) % q.size()], p)) return true;
    return false;
}

}  // namespace g2d::rt
