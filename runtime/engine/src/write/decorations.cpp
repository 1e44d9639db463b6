#include "g2d/decorations.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "g2d/rng.hpp"

namespace g2d::rt {

namespace {

constexpr double kPi = 3.141592653589793;

double degreesOf(vec2 v) { return std::atan2(v.y, v.x) * 180.0 / kPi; }

// Even-odd: inside the outer ring and outside its holes.
bool insideRings(const DrawItem& it, vec2 p) {
    bool in = false;
    auto ring = [&](const std::vector<vec2>& r) {
        for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
            if ((r[i].y > p.y) != (r[j].y > p.y) && p.x < r[j].x + (p.y - r[j].y) / (r[i].y - r[j].y) * (r[i].x - r[j].x)) in = !in;
    };
    if (it.corners.size() < 3) return false;
    ring(it.corners);
    for (const auto& h : it.holes)
        if (h.size() >= 3) ring(h);
    return in;
}

double ringArea(const std::vector<vec2>& r) {
    double a = 0;
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) a += cross(r[j], r[i]);
    return std::abs(a) / 2;
}

void edgeTiles(const DrawItem& it, double w, double h, double turn, std::vector<Placement>& out) {
    std::vector<vec2> path{it.a};
    path.insert(path.end(), it.bend.begin(), it.bend.end());
    path.push_back(it.b);
    double total = 0;
    for (std::size_t i = 1; i < path.size(); ++i) total += length(path[i] - path[i - 1]);
    if (!(total > 0)) return;
    const double every = styleNumber(it, "decor_every", 0);
    const double n = every > 0 ? std::max(1.0, std::round(total / every)) : 1.0;
    const auto tiles = static_cast<std::size_t>(std::min(n, double(kMaxDecorations)));
    const double tile = total / static_cast<double>(tiles);
    const double offset = styleNumber(it, "decor_offset", 0);
    std::size_t seg = 1;
    double before = 0;   // the path's length before segment seg
    for (std::size_t k = 0; k < tiles; ++k) {
        const double s = (static_cast<double>(k) + 0.5) * tile;
        while (seg + 1 < path.size() && before + length(path[seg] - path[seg - 1]) < s) before += length(path[seg] - path[seg - 1]), ++seg;
        const vec2 d = path[seg] - path[seg - 1];
        const double l = length(d);
        const vec2 u = l > 0 ? d * (1 / l) : vec2(1, 0);
        const vec2 at = path[seg - 1] + u * std::clamp(s - before, 0.0, l) + vec2(-u.y, u.x) * offset;
        out.push_back({at, degreesOf(u) + turn, w > 0 ? w : tile, h});
    }
}

void faceGrid(const DrawItem& it, double spacing, double w, double h, double turn, std::vector<Placement>& out) {
    double x0 = it.corners[0].x, x1 = x0, y0 = it.corners[0].y, y1 = y0;
    for (const vec2& p : it.corners) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    const double cells = ((x1 - x0) / spacing + 1) * ((y1 - y0) / spacing + 1);
    if (!(cells < 4.0 * kMaxDecorations)) return;   // a spacing far finer than the face: nothing rather than a flood
    for (double j = std::ceil(y0 / spacing); j * spacing <= y1; ++j)
        for (double i = std::ceil(x0 / spacing); i * spacing <= x1; ++i) {
            const vec2 p{i * spacing, j * spacing};
            if (out.size() < kMaxDecorations && insideRings(it, p)) out.push_back({p, turn, w, h});
        }
}

void faceScatter(const DrawItem& it, double density, double w, double h, double turn, std::vector<Placement>& out) {
    double area = ringArea(it.corners);
    for (const auto& hole : it.holes) area -= ringArea(hole);
    const double want = std::min(std::round(density * area), double(kMaxDecorations));
    if (!(want >= 1)) return;
    double x0 = it.corners[0].x, x1 = x0, y0 = it.corners[0].y, y1 = y0;
    for (const vec2& p : it.corners) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    // Dart throwing: a least distance of 0.7 / sqrt(density) keeps the
    // placements apart (a Poisson-disk look) and still fits the count.
    const double least = 0.7 / std::sqrt(density);
    Rng rng(0x9e3779b97f4a7c15ull ^ (static_cast<std::uint64_t>(it.id) * 0xbf58476d1ce4e5b9ull));
    const auto count = static_cast<std::size_t>(want);
    // Placements by cell of side `least`: a closer one is in the 3 × 3 around.
    std::unordered_map<std::uint64_t, std::vector<vec2>> cells;
    auto cellOf = [&](double x, double y) {
        return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::floor((x - x0) / least))) << 32) |
               static_cast<std::uint32_t>(std::floor((y - y0) / least));
    };
    for (std::size_t tries = 0; out.size() < count && tries < 30 * count; ++tries) {
        const vec2 p{rng.uniform(x0, x1), rng.uniform(y0, y1)};
        if (!insideRings(it, p)) continue;
        bool apart = true;
        for (int dx = -1; dx <= 1 && apart; ++dx)
            for (int dy = -1; dy <= 1 && apart; ++dy)
                if (auto c = cells.find(cellOf(p.x + dx * least, p.y + dy * least)); c != cells.end())
                    for (const vec2& q : c->second) apart = apart && length(q - p) >= least;
        if (!apart) continue;
        cells[cellOf(p.x, p.y)].push_back(p);
        out.push_back({p, turn, w, h});
    }
}

}  // namespace

DecorShape decorShape(const DrawItem& it) {
    const Value* tag = styleValue(it, "decor_tag");
    if (!tag) return styleValue(it, "decor_href") ? DecorShape::Image : DecorShape::None;
    const std::string t = toString(*tag);
    return t == "image" ? DecorShape::Image : t == "rect" ? DecorShape::Rect : t == "circle" ? DecorShape::Circle : DecorShape::None;
}

bool isPlacementProp(std::string_view prop) {
    static constexpr std::string_view kPlacing[] = {"decor_tag", "decor_href", "decor_width", "decor_height", "decor_rotate",
                                                    "decor_every", "decor_density", "decor_offset", "decor_r"};
    return std::find(std::begin(kPlacing), std::end(kPlacing), prop) != std::end(kPlacing);
}

std::vector<Placement> decorPlacements(const DrawItem& it) {
    std::vector<Placement> out;
    if (decorShape(it) == DecorShape::None) return out;
    const double turn = styleNumber(it, "decor_rotate", 0);
    if (it.cls == ElemClass::Edge) {
        edgeTiles(it, styleNumber(it, "decor_width", 0), styleNumber(it, "decor_height", 0.2), turn, out);
        return out;
    }
    const double w = styleNumber(it, "decor_width", 0.5), h = styleNumber(it, "decor_height", 0.5);
    if (it.cls == ElemClass::Face && it.corners.size() >= 3) {
        const double spacing = styleNumber(it, "decor_every", 0), density = styleNumber(it, "decor_density", 0);
        if (density > 0) return faceScatter(it, density, w, h, turn, out), out;
        if (spacing > 0) return faceGrid(it, spacing, w, h, turn, out), out;
    }
    out.push_back({it.a, turn, w, h});
    return out;
}

}  // namespace g2d::rt
