#include "g2d/placement.hpp"

#include <algorithm>
#include <cmath>

namespace g2d::rt {

namespace {

constexpr double kEps = 1e-12;

vec2 mean(const std::vector<vec2>& ps) {
    vec2 c{0, 0};
    for (const auto& p : ps) c += p;
    return ps.empty() ? c : c / static_cast<double>(ps.size());
}

struct Moments {
    double sxx = 0, sxy = 0, syy = 0;
};

Moments moments(const std::vector<vec2>& ps) {
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

// The direction of a point set: along the directed edge if given; else its
// total-least-squares line, taken pointing right (angle in (-90°, 90°]) as the
// thesis's tool did, so that a mirrored match of a symmetric pattern is not
// turned upside down; a set with no principal axis (isotropic, e.g. a square
// or a diamond) lies along the x axis, as a least-squares fit of it does.
vec2 direction(const std::vector<vec2>& ps, std::optional<std::pair<int, int>> edge) {
    if (edge) {
        const vec2 u = ps[edge->second] - ps[edge->first];
        const double l = length(u);
        return l > kEps ? u / l : vec2{1, 0};
    }
    if (ps.size() < 2) return {1, 0};
    const Moments m = moments(ps);
    if (isotropic(m)) return {1, 0};
    const double theta = 0.5 * std::atan2(2 * m.sxy, m.sxx - m.syy);
    vec2 u{std::cos(theta), std::sin(theta)};
    // (A vertical line's cos(±90°) is ±6e-17: within 1e-9 it counts as vertical.)
    if (u.x < -1e-9 || (std::abs(u.x) <= 1e-9 && u.y < 0)) u = -u;
    return u;
}

double extent(const std::vector<vec2>& ps, vec2 axis) {
    if (ps.empty()) return 0;
    double lo = dot(ps[0], axis), hi = lo;
    for (const auto& p : ps) {
        const double t = dot(p, axis);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
    return hi - lo;
}

}  // namespace

vec2 PlacementFrame::place(vec2 sketch) const {
    const vec2 o = sketch - cD;
    return cH + su * dot(o, uM) * uH + sw * dot(o, wM) * wH;
}

PlacementFrame placementFrame(const std::vector<vec2>& mother, const std::vector<vec2>& host,
                              std::optional<std::pair<int, int>> directedEdge,
                              const std::vector<vec2>& refDaughter, const std::vector<vec2>& refHost) {
    PlacementFrame f;
    f.cD = mean(refDaughter);
    f.cH = mean(refHost);
    f.uM = direction(mother, directedEdge);
    f.uH = direction(host, directedEdge);
    f.wM = perpLeft(f.uM);
    f.wH = perpLeft(f.uH);
    const double mu = extent(mother, f.uM), mw = extent(mother, f.wM);
    const double hu = extent(host, f.uH), hw = extent(host, f.wH);
    // An axis along which the mother sketch is flat keeps the sketch's scale (1),
    // as in the thesis's tool.
    f.su = mu > kEps ? hu / mu : 1;
    f.sw = mw > kEps ? hw / mw : 1;
    return f;
}

}  // namespace g2d::rt
