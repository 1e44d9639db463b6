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

// Principal axis of the points (total least squares), oriented first → last.
vec2 direction(const std::vector<vec2>& ps, std::optional<std::pair<int, int>> edge) {
    vec2 u{0, 0};
    if (edge) {
        u = ps[edge->second] - ps[edge->first];
    } else if (ps.size() >= 2) {
        const vec2 c = mean(ps);
        double sxx = 0, sxy = 0, syy = 0;
        for (const auto& p : ps) {
            const vec2 d = p - c;
            sxx += d.x * d.x;
            sxy += d.x * d.y;
            syy += d.y * d.y;
        }
        if (sxx + syy > kEps) {
            const double theta = 0.5 * std::atan2(2 * sxy, sxx - syy);
            u = {std::cos(theta), std::sin(theta)};
            const vec2 span = ps.back() - ps.front();
            if (dot(u, span) < 0) u = -u;
        }
    }
    const double l = length(u);
    return l > kEps ? u / l : vec2{1, 0};
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

PlacementFrame placementFrame(const std::vector<vec2>& mother, const std::vector<vec2>& daughter,
                              const std::vector<vec2>& host, std::optional<std::pair<int, int>> directedEdge) {
    PlacementFrame f;
    f.cD = mean(daughter);
    f.cH = mean(host);
    f.uM = direction(mother, directedEdge);
    f.uH = direction(host, directedEdge);
    f.wM = perpLeft(f.uM);
    f.wH = perpLeft(f.uH);
    const double mu = extent(mother, f.uM), mw = extent(mother, f.wM);
    const double hu = extent(host, f.uH), hw = extent(host, f.wH);
    const bool du = mu > kEps, dw = mw > kEps;
    f.su = du ? hu / mu : 1;
    f.sw = dw ? hw / mw : 1;
    if (!du && dw) f.su = f.sw;
    if (du && !dw) f.sw = f.su;
    return f;
}

}  // namespace g2d::rt
