#include "g2d/geometry3.hpp"
#include "g2d/plane_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <tuple>
#include <utility>

#include <glm/geometric.hpp>

namespace g2d::rt {
namespace {

constexpr double kRelEps = 1e-9;

double det3(vec3 a, vec3 b, vec3 c) { return glm::dot(a, glm::cross(b, c)); }

double maxAbs(vec3 v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// The size of a configuration: its largest coordinate difference from its
// first point (translation-invariant, unlike the coordinates themselves).
double sizeOf(std::span<const vec3> points) {
    double size = 0;
    for (const vec3& p : points) size = std::max(size, maxAbs(p - points[0]));
    return size;
}
double epsOf(std::initializer_list<vec3> points) { return kRelEps * sizeOf({points.begin(), points.size()}); }

double pointSegmentDistance(vec3 p, vec3 a, vec3 b) {
    const vec3 d = b - a;
    const double l2 = glm::dot(d, d);
    const double t = l2 > 0 ? std::clamp(glm::dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * d));
}

double segmentDistanceEps(vec3 a0, vec3 a1, vec3 b0, vec3 b1, double eps) {
    const vec3 da = a1 - a0, db = b1 - b0;
    const double la = glm::length(da), lb = glm::length(db);
    if (la <= eps) return pointSegmentDistance(a0, b0, b1);
    if (lb <= eps) return pointSegmentDistance(b0, a0, a1);
    const vec3 c = glm::cross(da, db);
    const double cl = glm::length(c);
    if (cl <= kRelEps * la * lb) {
        // Case 1, parallel: the line distance ‖w − (w·d̂)d̂‖ (OC-5), then the
        // gap between the intervals both project to on a's line.
        const vec3 dh = da / la, w = b0 - a0;
        const double along0 = glm::dot(w, dh), along1 = glm::dot(b1 - a0, dh);
        const double d = glm::length(w - along0 * dh);
        const double gap = std::max({0.0, std::min(along0, along1) - la, -std::max(along0, along1)});
        return std::hypot(d, gap);
    }
    // Cases 2 and 3: the lines' closest points, eqs (3.3), (3.4).
    const vec3 w = b0 - a0;
    const double s = det3(w, db, c) / (cl * cl), t = det3(w, da, c) / (cl * cl);
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) return glm::length((a0 + s * da) - (b0 + t * db));
    // Outside a segment: the squared distance is convex in (s, t), so its
    // minimum over the segments lies on an end of one of them.
    return std::min({pointSegmentDistance(a0, b0, b1), pointSegmentDistance(a1, b0, b1),
                     pointSegmentDistance(b0, a0, a1), pointSegmentDistance(b1, a0, a1)});
}

// The open segments a0a1 and b0b1 share a point (by more than eps): crossing
// inside both, or collinear and overlapping over a length.
bool openSegmentsMeet(vec3 a0, vec3 a1, vec3 b0, vec3 b1) {
    const double eps = epsOf({a0, a1, b0, b1});
    const vec3 da = a1 - a0, db = b1 - b0;
    const double la = glm::length(da), lb = glm::length(db);
    if (la <= eps || lb <= eps) return false;
    const vec3 c = glm::cross(da, db), w = b0 - a0;
    const double cl = glm::length(c);
    if (cl <= kRelEps * la * lb) {
        const vec3 dh = da / la;
        const double along0 = glm::dot(w, dh), along1 = glm::dot(b1 - a0, dh);
        if (glm::length(w - along0 * dh) > eps) return false;
        return std::min(la, std::max(along0, along1)) - std::max(0.0, std::min(along0, along1)) > eps;
    }
    const double s = det3(w, db, c) / (cl * cl), t = det3(w, da, c) / (cl * cl);
    if (s * la <= eps || (1 - s) * la <= eps || t * lb <= eps || (1 - t) * lb <= eps) return false;
    return glm::length((a0 + s * da) - (b0 + t * db)) <= eps;
}

// Signed distance of q from the line a→b in the plane with normal n (unit
// scale not needed): positive on the left seen from n's tip.
double sideDistance(vec3 a, vec3 b, vec3 q, vec3 n) {
    return glm::dot(glm::cross(b - a, q - a), n) / (glm::length(b - a) * glm::length(n));
}

// q (in the triangle's plane) strictly inside p0p1p2, whose normal is n.
bool insideOpenTriangle(vec3 q, vec3 p0, vec3 p1, vec3 p2, vec3 n, double eps) {
    return sideDistance(p0, p1, q, n) > eps && sideDistance(p1, p2, q, n) > eps && sideDistance(p2, p0, q, n) > eps;
}

// A triangle whose height over its longest side is within eps has no interior.
bool degenerateTriangle(vec3 p0, vec3 p1, vec3 p2, double eps) {
    const double longest = std::max({glm::length(p1 - p0), glm::length(p2 - p1), glm::length(p0 - p2)});
    return glm::length(glm::cross(p1 - p0, p2 - p0)) <= eps * longest;
}

// Newell's sum: twice the vector area, for planar and non-planar outlines.
vec3 newellSum(std::span<const vec3> polygon) {
    vec3 sum(0.0);
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
        sum += glm::cross(polygon[i] - polygon[0], polygon[i + 1] - polygon[0]);
    return sum;
}

// --- triangulation, in the 2D view ---

double pointSegmentDistance2(vec2 p, vec2 a, vec2 b) { return std::sqrt(pointSegmentDistanceSquared(p, a, b)); }

// Crossing test ([AMHH08] §16.9.1): a ray towards +x crosses the outline an
// odd number of times.
bool insidePolygon2(vec2 p, const std::vector<vec2>& outline) {
    bool inside = false;
    for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
        const vec2 a = outline[i], b = outline[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
    }
    return inside;
}

struct Diagonals {
    const std::vector<vec2>& q;
    double eps;
    std::vector<std::pair<int, int>> kept;

    // Segment i–j meets segment c–d other than at a shared end.
    bool meets(int i, int j, int c, int d) const {
        const bool sharesI = c == i || d == i, sharesJ = c == j || d == j;
        // An end lying on the other segment (touching, or overlapping when
        // collinear).
        if (!sharesI && !sharesJ) {
            if (pointSegmentDistance2(q[c], q[i], q[j]) <= eps || pointSegmentDistance2(q[d], q[i], q[j]) <= eps) return true;
        }
        if (!sharesI && pointSegmentDistance2(q[i], q[c], q[d]) <= eps) return true;
        if (!sharesJ && pointSegmentDistance2(q[j], q[c], q[d]) <= eps) return true;
        if (sharesI || sharesJ) return false;
        return segmentsCrossProperly(q[i], q[j], q[c], q[d]);
    }

    // §3.2.4 steps 2 and 3: crosses no side and no kept diagonal, passes
    // through no vertex, and its midpoint is inside.
    bool valid(int i, int j) const {
        const int n = static_cast<int>(q.size());
        for (int v = 0; v < n; ++v)
            if (v != i && v != j && pointSegmentDistance2(q[v], q[i], q[j]) <= eps) return false;
        for (int v = 0; v < n; ++v)
            if (meets(i, j, v, (v + 1) % n)) return false;
        for (const auto& [c, d] : kept)
            if (meets(i, j, c, d)) return false;
        return insidePolygon2((q[i] + q[j]) * 0.5, q);
    }
};

// Splits the sub-polygon `ids` (ascending original indices, which is its
// cyclic order) along a kept diagonal until only triangles are left.
void splitAlong(const std::vector<int>& ids, const std::vector<std::pair<int, int>>& kept,
                std::vector<std::array<int, 3>>& out) {
    if (ids.size() == 3) {
        out.push_back({ids[0], ids[1], ids[2]});
        return;
    }
    const auto pos = [&](int v) { return std::find(ids.begin(), ids.end(), v) - ids.begin(); };
    const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(ids.size());
    for (const auto& [c, d] : kept) {
        const std::ptrdiff_t a = pos(c), b = pos(d);
        if (a == m || b == m || b - a == 1 || (a == 0 && b == m - 1)) continue;
        std::vector<int> inner(ids.begin() + a, ids.begin() + b + 1), outer(ids.begin(), ids.begin() + a + 1);
        outer.insert(outer.end(), ids.begin() + b, ids.end());
        splitAlong(inner, kept, out);
        splitAlong(outer, kept, out);
        return;
    }
}

std::vector<std::array<int, 3>> fan(int n) {
    std::vector<std::array<int, 3>> out;
    for (int i = 1; i + 1 < n; ++i) out.push_back({0, i, i + 1});
    return out;
}

// Sides and diagonals of a triangulation: the diagonals are the triangle
// edges that are not sides of the n-gon.
bool isSide(int a, int b, int n) { return b - a == 1 || (a == 0 && b == n - 1); }

std::vector<std::pair<int, int>> diagonalsOf(const std::vector<std::array<int, 3>>& triangles, int n) {
    std::vector<std::pair<int, int>> out;
    for (const auto& t : triangles)
        for (const auto& [a, b] : {std::pair{t[0], t[1]}, std::pair{t[1], t[2]}, std::pair{t[0], t[2]}})
            if (!isSide(a, b, n)) out.emplace_back(a, b);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace

double segmentDistance(vec3 a0, vec3 a1, vec3 b0, vec3 b1) {
    return segmentDistanceEps(a0, a1, b0, b1, epsOf({a0, a1, b0, b1}));
}

bool segmentsIntersect(vec3 a0, vec3 a1, vec3 b0, vec3 b1, double h) {
    const double eps = epsOf({a0, a1, b0, b1});
    return segmentDistanceEps(a0, a1, b0, b1, eps) <= h + eps;
}

bool segmentsIntersectSharing(vec3 shared, vec3 a, vec3 b, double h) {
    const double eps = epsOf({shared, a, b});
    return pointSegmentDistance(a, shared, b) <= h + eps || pointSegmentDistance(b, shared, a) <= h + eps;
}

double edgeThickness(double a0Radius, double a1Radius, double b0Radius, double b1Radius) {
    return (a0Radius + a1Radius) / 2 + (b0Radius + b1Radius) / 2;
}

bool segmentTriangle(vec3 o0, vec3 o1, vec3 p0, vec3 p1, vec3 p2) {
    const double eps = epsOf({o0, o1, p0, p1, p2});
    const vec3 dir = o1 - o0, e1 = p1 - p0, e2 = p2 - p0, n = glm::cross(e1, e2);
    if (glm::length(dir) <= eps || degenerateTriangle(p0, p1, p2, eps)) return false;
    // The ends' signed distances from the plane decide the thesis's cases
    // with one tolerance: both within eps is the coplanar (parallel, d = 0)
    // case; otherwise the open segment must cross the plane, which is
    // 0 < t < l with the margin measured off the plane.
    const double nl = glm::length(n);
    const double d0 = glm::dot(o0 - p0, n) / nl, d1 = glm::dot(o1 - p0, n) / nl;
    if (std::abs(d0) <= eps && std::abs(d1) <= eps) {
        // 2D case (§3.2.2): apart if the triangle lies on one side of the
        // segment's line, or both ends lie beyond one of its sides.
        const double s0 = sideDistance(o0, o1, p0, n), s1 = sideDistance(o0, o1, p1, n), s2 = sideDistance(o0, o1, p2, n);
        if ((s0 <= eps && s1 <= eps && s2 <= eps) || (s0 >= -eps && s1 >= -eps && s2 >= -eps)) return false;
        for (const auto& [a, b] : {std::pair{p0, p1}, std::pair{p1, p2}, std::pair{p2, p0}})
            if (sideDistance(a, b, o0, n) <= eps && sideDistance(a, b, o1, n) <= eps) return false;
        return true;
    }
    if (!((d0 < -eps && d1 > eps) || (d0 > eps && d1 < -eps))) return false;
    // Eqs (3.9), (3.10); each barycentric coordinate times its vertex's
    // height is the hit's distance from the opposite side, which must exceed eps.
    const vec3 s = o0 - p0;
    const double det = det3(-dir, e1, e2);
    const double u = det3(-dir, s, e2) / det, v = det3(-dir, e1, s) / det;
    return u * nl / glm::length(e2) > eps && v * nl / glm::length(e1) > eps &&
           (1 - u - v) * nl / glm::length(p2 - p1) > eps;
}

bool trianglesIntersect(vec3 p0, vec3 p1, vec3 p2, vec3 q0, vec3 q1, vec3 q2) {
    if (segmentTriangle(p0, p1, q0, q1, q2) || segmentTriangle(p1, p2, q0, q1, q2) ||
        segmentTriangle(p2, p0, q0, q1, q2) || segmentTriangle(q0, q1, p0, p1, p2) ||
        segmentTriangle(q1, q2, p0, p1, p2) || segmentTriangle(q2, q0, p0, p1, p2))
        return true;
    const double eps = epsOf({p0, p1, p2, q0, q1, q2});
    if (degenerateTriangle(p0, p1, p2, eps) || degenerateTriangle(q0, q1, q2, eps)) return false;
    const vec3 n = glm::cross(p1 - p0, p2 - p0), nh = glm::normalize(n);
    for (const vec3& q : {q0, q1, q2})
        if (std::abs(glm::dot(q - p0, nh)) > eps) return false;
    // Coplanar, and no edge enters the other: either apart or equal.
    return insideOpenTriangle((q0 + q1 + q2) / 3.0, p0, p1, p2, n, eps);
}

std::vector<std::array<int, 3>> triangulate(std::span<const vec3> polygon) {
    const int n = static_cast<int>(polygon.size());
    if (n < 3) return {};
    if (n == 3) return {{0, 1, 2}};
    const double size = sizeOf(polygon), eps = kRelEps * size;
    const vec3 normal = newellSum(polygon);
    if (glm::length(normal) <= eps * size) return fan(n);
    // The 2D view: drop the axis the normal leans on most.
    const int drop = std::abs(normal.x) >= std::abs(normal.y) && std::abs(normal.x) >= std::abs(normal.z) ? 0
                     : std::abs(normal.y) >= std::abs(normal.z)                                         ? 1
                                                                                                          : 2;
    std::vector<vec2> q;
    for (const vec3& p : polygon) q.emplace_back(p[(drop + 1) % 3], p[(drop + 2) % 3]);

    std::vector<std::tuple<double, int, int>> candidates;
    for (int i = 0; i < n; ++i)
        for (int j = i + 2; j < n; ++j)
            if (!isSide(i, j, n)) {
                const vec3 d = polygon[j] - polygon[i];
                candidates.emplace_back(glm::dot(d, d), i, j);
            }
    std::sort(candidates.begin(), candidates.end());
    Diagonals diagonals{q, eps, {}};
    for (const auto& [length2, i, j] : candidates) {
        if (static_cast<int>(diagonals.kept.size()) == n - 3) break;
        if (diagonals.valid(i, j)) diagonals.kept.emplace_back(i, j);
    }
    if (static_cast<int>(diagonals.kept.size()) != n - 3) return fan(n);

    std::vector<int> all(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) all[static_cast<std::size_t>(i)] = i;
    std::vector<std::array<int, 3>> out;
    splitAlong(all, diagonals.kept, out);
    if (static_cast<int>(out.size()) != n - 2) return fan(n);  // the diagonals did not nest
    std::sort(out.begin(), out.end());
    return out;
}

double polygonArea3(std::span<const vec3> polygon) {
    const auto at = [&](int i) { return polygon[static_cast<std::size_t>(i)]; };
    double area = 0;
    for (const auto& t : triangulate(polygon)) area += glm::length(glm::cross(at(t[1]) - at(t[0]), at(t[2]) - at(t[0]))) / 2;
    return area;
}

vec3 faceNormal(vec3 prev, vec3 p, vec3 next) {
    const vec3 a = next - p, b = prev - p, c = glm::cross(a, b);
    const double l = glm::length(c);
    return l > kRelEps * glm::length(a) * glm::length(b) ? c / l : vec3(0.0);
}

vec3 polygonNormal(std::span<const vec3> polygon) {
    if (polygon.size() < 3) return vec3(0.0);
    const vec3 sum = newellSum(polygon);
    const double l = glm::length(sum), size = sizeOf(polygon);
    return l > kRelEps * size * size ? sum / l : vec3(0.0);
}

bool segmentPolygon(vec3 o0, vec3 o1, std::span<const vec3> polygon) {
    const auto at = [&](int i) { return polygon[static_cast<std::size_t>(i)]; };
    const auto triangles = triangulate(polygon);
    for (const auto& t : triangles)
        if (segmentTriangle(o0, o1, at(t[0]), at(t[1]), at(t[2]))) return true;
    for (const auto& [a, b] : diagonalsOf(triangles, static_cast<int>(polygon.size())))
        if (openSegmentsMeet(o0, o1, at(a), at(b))) return true;
    return false;
}

bool polygonsIntersect(std::span<const vec3> p, std::span<const vec3> q) {
    const auto tp = triangulate(p), tq = triangulate(q);
    const auto pt = [&](int i) { return p[static_cast<std::size_t>(i)]; };
    const auto qt = [&](int i) { return q[static_cast<std::size_t>(i)]; };
    for (const auto& a : tp)
        for (const auto& b : tq)
            if (trianglesIntersect(pt(a[0]), pt(a[1]), pt(a[2]), qt(b[0]), qt(b[1]), qt(b[2]))) return true;
    // Sides and diagonals of one against the diagonals of the other.
    const int np = static_cast<int>(p.size()), nq = static_cast<int>(q.size());
    const auto dp = diagonalsOf(tp, np), dq = diagonalsOf(tq, nq);
    for (int i = 0; i < np; ++i)
        for (const auto& [c, d] : dq)
            if (openSegmentsMeet(pt(i), pt((i + 1) % np), qt(c), qt(d))) return true;
    for (int i = 0; i < nq; ++i)
        for (const auto& [c, d] : dp)
            if (openSegmentsMeet(qt(i), qt((i + 1) % nq), pt(c), pt(d))) return true;
    for (const auto& [a, b] : dp)
        for (const auto& [c, d] : dq)
            if (openSegmentsMeet(pt(a), pt(b), qt(c), qt(d))) return true;
    return false;
}

}  // namespace g2d::rt
