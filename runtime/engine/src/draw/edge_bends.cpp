#include "g2d/edge_bends.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "g2d/angle_drawing.hpp"

namespace g2d::rt {

namespace {

// One bent edge: its segments' wanted vectors before scaling (the offsets
// are drawn once, so every redraw halves the same wander).
struct BentEdge {
    EdgeId id;
    int segments;
    std::vector<double> heading;   // per segment: the summed, smoothed offset (radians)
    vec2 along;                    // the edge's vector / segments, as the derivation drew it
    double scale = 1;              // halved on each conflict; 0: straight
    std::uint32_t firstPoint;      // its interior points' indices: firstPoint .. firstPoint + segments - 2
};

// Every drawn point: node positions (index = node id), then interior points.
struct Points {
    std::vector<vec2> at;
    std::vector<int> unknown;   // per point: its unknown's index, or -1 (fixed)
};

std::vector<double> headings(int segments, int smooth, double amplitude, Rng& rng) {
    std::vector<double> noise(static_cast<std::size_t>(segments + smooth - 1));
    for (double& u : noise) u = rng.uniform(-amplitude, amplitude);
    std::vector<double> out(static_cast<std::size_t>(segments));
    double window = 0, sum = 0;
    for (int k = 0; k < smooth; ++k) window += noise[static_cast<std::size_t>(k)];
    for (int k = 0; k < segments; ++k) {
        if (k > 0) window += noise[static_cast<std::size_t>(k + smooth - 1)] - noise[static_cast<std::size_t>(k - 1)];
        sum += window / smooth;
        out[static_cast<std::size_t>(k)] = sum;
    }
    return out;
}

vec2 turned(vec2 v, double a) {
    const double c = std::cos(a), s = std::sin(a);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}

// The point indices of edge `b`'s polyline, source to target.
template <class F>
void eachPoint(const Graph& g, const BentEdge& b, F f) {
    f(static_cast<std::uint32_t>(g.source(b.id)));
    for (int k = 1; k < b.segments; ++k) f(b.firstPoint + static_cast<std::uint32_t>(k - 1));
    f(static_cast<std::uint32_t>(g.target(b.id)));
}

struct Segment {
    std::uint32_t p, q;   // point indices
    std::uint32_t edge;   // index into the bent edges, or kStraight
};
constexpr std::uint32_t kStraight = 0xffffffffu;

// Which bent edges conflict: a polyline that crosses, overlaps or comes
// within `clearance` of another (or of itself) away from a shared point,
// as the drawing step's planarity test says (conflictingItems). The items are
// the segments, and the nodes without edges.
std::vector<char> conflicts(const std::vector<Segment>& segs, const std::vector<std::pair<int, int>>& lone, const std::vector<vec2>& at,
                            std::size_t bentCount, double clearance) {
    std::vector<char> bad(bentCount, 0);
    std::vector<std::pair<int, int>> items;
    items.reserve(segs.size() + lone.size());
    for (const Segment& s : segs) items.emplace_back(static_cast<int>(s.p), static_cast<int>(s.q));
    items.insert(items.end(), lone.begin(), lone.end());
    for (const auto& [i, j] : conflictingItems(at, items, clearance)) {
        const std::uint32_t a = static_cast<std::size_t>(i) < segs.size() ? segs[static_cast<std::size_t>(i)].edge : kStraight;
        const std::uint32_t b = static_cast<std::size_t>(j) < segs.size() ? segs[static_cast<std::size_t>(j)].edge : kStraight;
        if (a != kStraight) bad[a] = 1;   // two straight ones: the derivation's own planar drawing
        if (b != kStraight) bad[b] = 1;
    }
    return bad;
}

// Per bent edge, the least index of a bent edge in its piece: the edges
// joined through nodes that move (a node with a straight edge is fixed, so
// it joins nothing).
std::vector<std::uint32_t> pieces(const Graph& g, const std::vector<BentEdge>& bent, const std::vector<int>& unknown) {
    std::vector<std::uint32_t> parent(bent.size());
    for (std::uint32_t i = 0; i < bent.size(); ++i) parent[i] = i;
    auto root = [&](std::uint32_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    std::unordered_map<NodeId, std::uint32_t> firstAt;   // a moving node -> a bent edge at it
    for (std::uint32_t i = 0; i < bent.size(); ++i)
        for (NodeId n : {g.source(bent[i].id), g.target(bent[i].id)}) {
            if (unknown[n] < 0) continue;
            auto [it, fresh] = firstAt.emplace(n, i);
            if (fresh) continue;
            const std::uint32_t a = root(i), b = root(it->second);
            parent[std::max(a, b)] = std::min(a, b);
        }
    for (std::uint32_t i = 0; i < bent.size(); ++i) parent[i] = root(i);
    return parent;
}

}  // namespace

BendResult bendEdges(Graph& g, const AngleLayoutSpec& spec, Rng& rng) {
    BendResult result;
    auto bendOf = [&](EdgeId e) {
        const auto k = static_cast<std::size_t>(g.edgeKind(e));
        return k < spec.kinds.size() ? spec.kinds[k].bend : 0.0;
    };
    bool any = false;
    for (const auto& k : spec.kinds) any = any || k.bend > 0;
    if (!any) return result;

    Points pts;
    pts.at.resize(g.nodeCapacity());
    for (NodeId n = 0; n < g.nodeCapacity(); ++n)
        if (g.nodeAlive(n)) pts.at[n] = g.pos(n);
    pts.unknown.assign(g.nodeCapacity(), -1);
    const std::vector<vec2> drawn = pts.at;

    // The bent edges, their offsets drawn in id order.
    std::vector<BentEdge> bent;
    std::vector<char> holdsStraight(g.nodeCapacity(), 0);
    std::vector<Segment> segs;
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e) {
        if (!g.edgeAlive(e)) continue;
        const vec2 a = g.pos(g.source(e)), b = g.pos(g.target(e));
        const double amplitude = bendOf(e);
        if (!(amplitude > 0) || g.source(e) == g.target(e)) {
            holdsStraight[g.source(e)] = holdsStraight[g.target(e)] = 1;
            segs.push_back({static_cast<std::uint32_t>(g.source(e)), static_cast<std::uint32_t>(g.target(e)), kStraight});
            continue;
        }
        const double n = std::round(length(b - a) / spec.bendSegment);
        const int segments = static_cast<int>(std::clamp(std::isfinite(n) ? n : 1.0, 1.0, double(kMaxBendSegments)));
        BentEdge be{e, segments, headings(segments, spec.bendSmooth, amplitude, rng), (b - a) * (1.0 / segments), 1,
                    static_cast<std::uint32_t>(pts.at.size())};
        for (int k = 1; k < segments; ++k) {
            pts.at.push_back(a + be.along * static_cast<double>(k));
            pts.unknown.push_back(-1);
        }
        bent.push_back(std::move(be));
    }
    if (bent.empty()) return result;

    // The unknowns: every interior point, and the nodes all of whose edges bend.
    int unknowns = 0;
    double segmentsTotal = 0;
    for (const BentEdge& b : bent) {
        segmentsTotal += b.segments;
        eachPoint(g, b, [&](std::uint32_t p) {
            if (p < g.nodeCapacity() && holdsStraight[p]) return;
            if (pts.unknown[p] < 0) pts.unknown[p] = unknowns++;
        });
    }
    const double anchor = 1.0 / (4.0 * segmentsTotal / static_cast<double>(bent.size()));

    // The normal equations' matrix does not depend on the wanted vectors:
    // factored once, solved once per round.
    std::vector<Eigen::Triplet<double>> t;
    for (const BentEdge& b : bent) {
        std::uint32_t prev = kStraight;
        eachPoint(g, b, [&](std::uint32_t p) {
            if (prev != kStraight) {
                const int i = pts.unknown[prev], j = pts.unknown[p];
                if (i >= 0) t.emplace_back(i, i, 1.0);
                if (j >= 0) t.emplace_back(j, j, 1.0);
                if (i >= 0 && j >= 0) t.emplace_back(i, j, -1.0), t.emplace_back(j, i, -1.0);
            }
            prev = p;
        });
    }
    for (NodeId n = 0; n < g.nodeCapacity(); ++n)
        if (pts.unknown[n] >= 0) t.emplace_back(pts.unknown[n], pts.unknown[n], anchor);
    Eigen::SparseMatrix<double> normal(unknowns, unknowns);
    normal.setFromTriplets(t.begin(), t.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);

    auto solve = [&] {
        Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, 2);
        auto add = [&](int i, vec2 v) {
            rhs(i, 0) += v.x;
            rhs(i, 1) += v.y;
        };
        for (const BentEdge& b : bent) {
            std::uint32_t prev = kStraight;
            int k = 0;
            eachPoint(g, b, [&](std::uint32_t p) {
                if (prev != kStraight) {
                    const vec2 want = turned(b.along, b.scale * b.heading[static_cast<std::size_t>(k++)]);
                    const int i = pts.unknown[prev], j = pts.unknown[p];
                    // p_j - p_i = want, with a fixed end moved to the right-hand side.
                    if (j >= 0) add(j, i >= 0 ? want : want + drawn[prev]);
                    if (i >= 0) add(i, j >= 0 ? want * -1.0 : drawn[p] - want);
                }
                prev = p;
            });
        }
        for (NodeId n = 0; n < g.nodeCapacity(); ++n)
            if (pts.unknown[n] >= 0) add(pts.unknown[n], drawn[n] * anchor);
        const Eigen::MatrixXd x = solver.solve(rhs);
        for (std::size_t p = 0; p < pts.at.size(); ++p)
            if (pts.unknown[p] >= 0) pts.at[p] = {x(pts.unknown[p], 0), x(pts.unknown[p], 1)};
    };

    const std::size_t straightSegments = segs.size();
    auto bentSegments = [&] {
        segs.resize(straightSegments);
        for (std::uint32_t bi = 0; bi < bent.size(); ++bi) {
            std::uint32_t prev = kStraight;
            eachPoint(g, bent[bi], [&](std::uint32_t p) {
                if (prev != kStraight) segs.push_back({prev, p, bi});
                prev = p;
            });
        }
    };
    bentSegments();
    const std::vector<std::uint32_t> piece = pieces(g, bent, pts.unknown);
    std::vector<std::pair<int, int>> lone;   // nodes without edges, which a bent edge may not touch either
    for (NodeId n = 0; n < g.nodeCapacity(); ++n)
        if (g.nodeAlive(n) && g.degree(n) == 0) lone.emplace_back(static_cast<int>(n), static_cast<int>(n));
    const double clearance = spec.settings.separation;
    bool planar = false;
    if (solver.info() == Eigen::Success) {
        for (int round = 0; round <= kBendRounds && !planar; ++round) {
            solve();
            bool finite = true;
            for (const vec2& p : pts.at) finite = finite && std::isfinite(p.x) && std::isfinite(p.y);
            if (!finite) break;
            const std::vector<char> bad = conflicts(segs, lone, pts.at, bent.size(), clearance);
            planar = std::find(bad.begin(), bad.end(), 1) == bad.end();
            // The first rounds cut the offending edges only; later ones every
            // edge of their pieces (a piece's shape depends on its own edges
            // alone), and the last undoes those pieces' bends, which leaves
            // them exactly as the derivation's planar drawing had them.
            std::vector<char> badPiece(bent.size(), 0);
            for (std::size_t i = 0; i < bent.size(); ++i)
                if (bad[i]) badPiece[piece[i]] = 1;
            for (std::size_t i = 0; i < bent.size(); ++i) {
                const bool cutting = round < kBendRounds / 2 ? bad[i] : badPiece[piece[i]];
                if (cutting) bent[i].scale = round + 1 == kBendRounds ? 0.0 : bent[i].scale / 2;
            }
        }
    }
    if (!planar) {   // as the derivation drew it
        pts.at.resize(drawn.size());
        std::copy(drawn.begin(), drawn.end(), pts.at.begin());
        for (BentEdge& b : bent) b.scale = 0, b.segments = 1;
    }
    for (NodeId n = 0; n < g.nodeCapacity(); ++n)
        if (g.nodeAlive(n) && pts.unknown[n] >= 0 && (pts.at[n].x != drawn[n].x || pts.at[n].y != drawn[n].y)) g.setPos(n, pts.at[n]);
    for (const BentEdge& b : bent) {
        std::vector<vec2> interior;
        for (int k = 1; k < b.segments; ++k) interior.push_back(pts.at[b.firstPoint + static_cast<std::uint32_t>(k - 1)]);
        g.setEdgeBend(b.id, std::move(interior));
        ++result.bent;
        if (b.scale < 1) ++result.reduced;
    }
    return result;
}

}  // namespace g2d::rt
