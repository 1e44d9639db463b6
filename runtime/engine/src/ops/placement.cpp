#include "g2d/placement.hpp"

#include <algorithm>
#include <cmath>

namespace g2d::rt {

namespace {

constexpr double kEps = 1e-12;

vec2 mean(std::span<const vec2> ps) {
    vec2 c{0, 0};
    for (const auto& p : ps) c += p;
    return ps.empty() ? c : c / static_cast<double>(ps.size());
}

struct Moments {
    double sxx = 0, sxy = 0, syy = 0;
};

Moments moments(std::span<const vec2> ps) {
    Moments m;
    const vec2 c = mean(ps);
    for (const auto& p : ps) {
        const vec2 d = p - c;
        m.sxx += d.x * d.x;
        m.sxy += d.x * d.y;
        m.syy += d.y * d.y;
    }
    return m;
}

// No principal axis: the two eigenvalues of the covariance are (nearly) equal.
bool isotropic(const Moments& m) {
    const double spread = m.sxx + m.syy;
    const double gap = std::hypot(m.sxx - m.syy, 2 * m.sxy);  // λ1 − λ2
    return spread <= kEps || gap <= 1e-9 * spread;
}

// The direction of a point set, as an angle: along the directed edge if given;
// else its total-least-squares line, taken pointing right (in (-90°, 90°]) as
// the thesis's tool did, so a mirrored match of a symmetric pattern is not
// turned upside down; 0 for a set with no principal axis (isotropic).
double direction(std::span<const vec2> ps, std::optional<std::pair<int, int>> edge) {
    if (edge) {
        const vec2 u = ps[edge->second] - ps[edge->first];
        return length(u) > kEps ? std::atan2(u.y, u.x) : 0.0;
    }
    if (ps.size() < 2) return 0;
    const Moments m = moments(ps);
    if (isotropic(m)) return 0;
    double theta = 0.5 * std::atan2(2 * m.sxy, m.sxx - m.syy);   // in [-90°, 90°]
    // A vertical line may come out as -90° by rounding: it points up.
    if (theta <= -1.5707963267948966 + 1e-9) theta += 3.141592653589793;
    return theta;
}

struct Extent {
    double x = 0, y = 0;
};

// The extents of the points `at` maps `ps` to.
template <class Map>
Extent extents(std::span<const vec2> ps, Map at) {
    if (ps.empty()) return {};
    const vec2 first = at(ps[0]);
    double x0 = first.x, x1 = x0, y0 = first.y, y1 = y0;
    for (const auto& q : ps) {
        const vec2 p = at(q);
        x0 = std::min(x0, p.x);
        x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y);
        y1 = std::max(y1, p.y);
    }
    return {x1 - x0, y1 - y0};
}

}  // namespace

vec2 PlacementFrame::place(vec2 sketch) const {
    const vec2 o = sketch - cD;
    const vec2 r{cosA * o.x - sinA * o.y, sinA * o.x + cosA * o.y};
    return cH + vec2{sx * r.x, sy * r.y};
}

PlacementFrame placementFrame(std::span<const vec2> mother, std::span<const vec2> host,
                              std::optional<std::pair<int, int>> directedEdge,
                              std::span<const vec2> refDaughter, std::span<const vec2> refHost,
                              std::span<const double> refZ) {
    PlacementFrame f;
    for (double z : refZ) f.z += z;
    if (!refZ.empty()) f.z /= static_cast<double>(refZ.size());
    f.cD = mean(refDaughter);
    f.cH = mean(refHost);
    const double delta = direction(host, directedEdge) - direction(mother, directedEdge);
    f.cosA = std::cos(delta);
    f.sinA = std::sin(delta);
    // The mother's extents once turned by Δ (no copy: this runs every step).
    const Extent m = extents(mother, [&](vec2 p) { return vec2{f.cosA * p.x - f.sinA * p.y, f.sinA * p.x + f.cosA * p.y}; });
    const Extent h = extents(host, [](vec2 p) { return p; });
    // An extent below 1e-9 of the larger one is rounding noise: no extent.
    const double tiny = 1e-9 * std::max({m.x, m.y, kEps});
    f.sx = m.x > tiny ? h.x / m.x : 1;
    f.sy = m.y > tiny ? h.y / m.y : 1;
    return f;
}

}  // namespace g2d::rt
