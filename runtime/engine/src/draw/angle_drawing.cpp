// Merrell 2023's drawing step (angle_drawing.hpp; digest D§5.3–5.4): builds
// A x = b over the free vertices and the lengths of the edges they touch,
// samples x̂ + K_A Λ, and frees a fixed neighbour after a failed system. The
// planarity test it accepts with is in angle_planarity.cpp.
//
// Random draws, in this order, all from the given Rng:
//   for each system built (i = 1..I), when A x = b is consistent:
//     when its solution is unique (K_A has no column): one sample, no draw;
//     otherwise for each sample (j = 1..J):
//       1. per non-rigid edge of E, by ascending edge index: a target length
//          Rng::uniform(minLength, maxLength), or for an edge with a unit
//          Rng::below(the count of its multiples in range), the multiple;
//       2. per component made only of free vertices, by ascending least
//          vertex: Rng::uniform for the x of its bounding box's low corner,
//          then one for its y (the box then lies in the canvas when it fits);
//   after a failed system that is not the last: one Rng::below(k) picking
//   the vertex to free among the k candidates in ascending index (no draw
//   when k = 0: the step stops).
// The step stops at the first accepted sample, drawing nothing more.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include <Eigen/Dense>

#include "g2d/angle_drawing.hpp"

namespace g2d::rt {

namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kRankTolerance = 1e-10;   // pivots below this · the largest count as zero (rank)
constexpr double kConsistency = 1e-9;      // consistent: ‖A x̂ − b‖ ≤ this · max(1, ‖b‖)
constexpr double kSlack = 1e-9;            // relative slack of the length, canvas and direction tests

bool finite(vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// One system: its unknowns are (x, y) of each free vertex (ascending), then
// the length of each non-rigid edge of E (ascending); rigid lengths are
// constants moved to b.
struct System {
    std::vector<int> freeVertices;       // F, ascending
    std::vector<int> column;             // per vertex: the column of its x (y: + 1), -1 when fixed
    std::vector<int> edges;              // E, ascending
    std::vector<int> sampled;            // the non-rigid edges of E, ascending (length columns, in order)
    std::vector<std::vector<int>> loose; // the components made only of free vertices, by least vertex
    bool consistent = false;
    double scale = 1;                    // the coordinates' magnitude, for the direction test
    VectorXd xhat;                       // minimum-norm least-squares solution
    MatrixXd kernel;                     // K_A, orthonormal columns
    Eigen::CompleteOrthogonalDecomposition<MatrixXd> lengthFit;   // of K_A's length rows
    bool lengthsMove = false;            // some sampled length varies in x̂ + K_A Λ
};

// A length in range that is a whole multiple of the edge's unit, uniformly
// among them (one Rng::below draw); the range's low end when none fits.
double unitMultiple(const AngleEdge& ed, Rng& rng) {
    const double lo = std::max(1.0, std::ceil(ed.minLength / ed.unit - kSlack)), hi = std::floor(ed.maxLength / ed.unit + kSlack);
    if (!(hi >= lo)) return ed.minLength;
    return ed.unit * (lo + static_cast<double>(rng.below(static_cast<std::uint64_t>(hi - lo) + 1)));
}

// Whether a length is a whole multiple of the edge's unit (or the edge has none).
bool onUnit(const AngleEdge& ed, double len) {
    if (!(ed.unit > 0)) return true;
    const double k = len / ed.unit;
    return std::abs(k - std::round(k)) <= kSlack * std::max(1.0, k) && std::round(k) >= 1;
}

int find(std::vector<int>& parent, int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

void build(const AngleGraph& g, const std::vector<char>& isFree, System& s) {
    const int nv = static_cast<int>(g.position.size());
    s.column.assign(g.position.size(), -1);
    for (int v = 0; v < nv; ++v)
        if (isFree[v]) {
            s.column[v] = 2 * static_cast<int>(s.freeVertices.size());
            s.freeVertices.push_back(v);
        }
    for (int e = 0; e < static_cast<int>(g.edges.size()); ++e) {
        const AngleEdge& ed = g.edges[e];
        if (isFree[ed.from] || isFree[ed.to] || (e < static_cast<int>(g.created.size()) && g.created[e])) {
            s.edges.push_back(e);
            if (ed.minLength != ed.maxLength) s.sampled.push_back(e);
        }
    }

    const Index rows = 2 * static_cast<Index>(s.edges.size());
    const Index cols = 2 * static_cast<Index>(s.freeVertices.size()) + static_cast<Index>(s.sampled.size());
    MatrixXd a = MatrixXd::Zero(rows, cols);
    VectorXd b = VectorXd::Zero(rows);
    Index lengthCol = 2 * static_cast<Index>(s.freeVertices.size());
    for (std::size_t k = 0; k < s.edges.size(); ++k) {
        // v_to − v_from − s·u = 0, known terms to the right.
        const AngleEdge& ed = g.edges[s.edges[k]];
        const Index r = 2 * static_cast<Index>(k);
        const vec2 u{std::cos(ed.angle), std::sin(ed.angle)};
        if (isFree[ed.to]) {
            a(r, s.column[ed.to]) += 1;
            a(r + 1, s.column[ed.to] + 1) += 1;
        } else {
            b(r) -= g.position[ed.to].x;
            b(r + 1) -= g.position[ed.to].y;
        }
        if (isFree[ed.from]) {
            a(r, s.column[ed.from]) -= 1;
            a(r + 1, s.column[ed.from] + 1) -= 1;
        } else {
            b(r) += g.position[ed.from].x;
            b(r + 1) += g.position[ed.from].y;
        }
        if (ed.minLength != ed.maxLength) {
            a(r, lengthCol) = -u.x;
            a(r + 1, lengthCol) = -u.y;
            ++lengthCol;
        } else {
            b(r) += ed.minLength * u.x;
            b(r + 1) += ed.minLength * u.y;
        }
    }

    if (cols == 0) {
        s.xhat = VectorXd(0);
        s.kernel = MatrixXd(0, 0);
    } else if (rows == 0) {   // only vertices without edges: everything is free
        s.xhat = VectorXd::Zero(cols);
        s.kernel = MatrixXd::Identity(cols, cols);
    } else {
        // A P = Q [T 0; 0 0] Z: x̂ = A⁺ b, and null(A) = P Zᵀ [0; I] (orthonormal columns).
        // Faster than an SVD on a new component's hundreds of unknowns.
        Eigen::CompleteOrthogonalDecomposition<MatrixXd> cod;
        cod.setThreshold(kRankTolerance);
        cod.compute(a);
        s.xhat = cod.solve(b);
        // Full rank: no kernel (Eigen would take an empty block of Z at a null pointer).
        if (cod.rank() == cols) s.kernel = MatrixXd(cols, 0);
        else s.kernel = cod.colsPermutation() * cod.matrixZ().bottomRows(cols - cod.rank()).transpose();
    }
    const double residual = rows == 0 ? 0.0 : (cols == 0 ? b.norm() : (a * s.xhat - b).norm());
    s.consistent = std::isfinite(residual) && s.xhat.allFinite() && residual <= kConsistency * std::max(1.0, b.norm());
    s.scale = std::max({1.0, rows ? b.lpNorm<Eigen::Infinity>() : 0.0, cols ? s.xhat.lpNorm<Eigen::Infinity>() : 0.0});
    if (!s.consistent || s.kernel.cols() == 0) return;

    if (!s.sampled.empty()) {
        // K_A's columns are orthonormal, so a length the system fixes (a side
        // tied to a rigid one) has rounding noise there, not zero: clear it,
        // or the fit's relative rank test would take the noise for freedom.
        MatrixXd lengths = s.kernel.bottomRows(static_cast<Index>(s.sampled.size()));
        lengths = lengths.unaryExpr([](double x) { return std::abs(x) <= kRankTolerance ? 0.0 : x; });
        s.lengthsMove = lengths.cwiseAbs().maxCoeff() > 0;
        s.lengthFit.setThreshold(kRankTolerance);
        if (s.lengthsMove) s.lengthFit.compute(lengths);
    }
    // Components of free vertices; one with an edge to a fixed vertex is anchored.
    const int nf = static_cast<int>(s.freeVertices.size());
    std::vector<int> parent(static_cast<std::size_t>(nf));
    std::iota(parent.begin(), parent.end(), 0);
    std::vector<char> anchored(static_cast<std::size_t>(nf), 0);
    for (int e : s.edges) {
        const int cf = s.column[g.edges[e].from], ct = s.column[g.edges[e].to];
        if (cf >= 0 && ct >= 0) parent[find(parent, cf / 2)] = find(parent, ct / 2);
    }
    for (int e : s.edges) {
        const int cf = s.column[g.edges[e].from], ct = s.column[g.edges[e].to];
        if ((cf >= 0) != (ct >= 0)) anchored[find(parent, (cf >= 0 ? cf : ct) / 2)] = 1;
    }
    std::vector<int> slot(static_cast<std::size_t>(nf), -1);
    for (int k = 0; k < nf; ++k) {
        const int root = find(parent, k);
        if (anchored[root]) continue;
        if (slot[root] < 0) {
            slot[root] = static_cast<int>(s.loose.size());
            s.loose.emplace_back();
        }
        s.loose[slot[root]].push_back(s.freeVertices[k]);
    }
}

// One sample of x̂ + K_A Λ: Λ fits the lengths to random targets (OM-31),
// then each loose component is moved to a random place in the canvas.
void sample(const AngleGraph& g, const DrawingSettings& st, const System& s, Rng& rng, std::vector<vec2>& pos) {
    VectorXd x = s.xhat;
    if (s.kernel.cols() > 0 && !s.sampled.empty()) {
        // Targets are drawn even when no length can move: the draws per sample stay as documented.
        const Index p = static_cast<Index>(s.sampled.size());
        VectorXd target(p);
        for (Index k = 0; k < p; ++k) {
            const AngleEdge& ed = g.edges[s.sampled[static_cast<std::size_t>(k)]];
            target(k) = ed.unit > 0 ? unitMultiple(ed, rng) : rng.uniform(ed.minLength, ed.maxLength);
        }
        // The least-squares Λ of least norm: lengths the system ties (a
        // rectangle's opposite sides) get the mean of their targets.
        if (s.lengthsMove) x += s.kernel * s.lengthFit.solve(target - s.xhat.tail(p));
    }
    for (int v : s.freeVertices) pos[v] = {x(s.column[v]), x(s.column[v] + 1)};
    for (const std::vector<int>& comp : s.loose) {
        vec2 lo = pos[comp[0]], hi = lo;
        for (int v : comp) {
            lo = {std::min(lo.x, pos[v].x), std::min(lo.y, pos[v].y)};
            hi = {std::max(hi.x, pos[v].x), std::max(hi.y, pos[v].y)};
        }
        const double nx = rng.uniform(st.canvasLo.x, std::max(st.canvasLo.x, st.canvasHi.x - (hi.x - lo.x)));
        const double ny = rng.uniform(st.canvasLo.y, std::max(st.canvasLo.y, st.canvasHi.y - (hi.y - lo.y)));
        const vec2 shift{nx - lo.x, ny - lo.y};
        for (int v : comp) pos[v] += shift;
    }
}

bool acceptable(const AngleGraph& g, const DrawingSettings& st, const System& s, const std::vector<vec2>& pos,
                std::vector<char>& moved) {
    const vec2 lo = st.canvasLo, hi = st.canvasHi;
    const double canvasSlack =
        kSlack * std::max({1.0, std::abs(lo.x), std::abs(lo.y), std::abs(hi.x), std::abs(hi.y)});
    for (int v : s.freeVertices) {
        const vec2 p = pos[v];
        if (!finite(p) || !(p.x >= lo.x - canvasSlack && p.x <= hi.x + canvasSlack && p.y >= lo.y - canvasSlack &&
                            p.y <= hi.y + canvasSlack))
            return false;
    }
    for (int e : s.edges) {
        const AngleEdge& ed = g.edges[e];
        const vec2 d = pos[ed.to] - pos[ed.from], u{std::cos(ed.angle), std::sin(ed.angle)};
        const double len = d.x * u.x + d.y * u.y, off = d.x * u.y - d.y * u.x;
        const double lengthSlack = kSlack * std::max(1.0, std::abs(ed.maxLength));
        if (!(len > 0 && len >= ed.minLength - lengthSlack && len <= ed.maxLength + lengthSlack) || !onUnit(ed, len)) return false;
        // Exact by construction up to rounding; a miss means a near-inconsistent system.
        if (!(std::abs(off) <= kSlack * s.scale)) return false;
    }
    if (s.edges.empty() && s.freeVertices.empty()) return true;
    // The moved vertices and the ends of created edges: every changed edge is tested.
    std::fill(moved.begin(), moved.end(), 0);
    for (int v : s.freeVertices) moved[v] = 1;
    for (int e : s.edges) moved[g.edges[e].from] = moved[g.edges[e].to] = 1;
    return drawingIsPlanar(pos, g.edges, st.separation, moved, g.surroundings) &&
           (!st.consistentAreas || areasConsistent(pos, g.edges, moved));
}

}  // namespace

DrawingResult drawAngleGraph(const AngleGraph& graph, const DrawingSettings& settings, Rng& rng) {
    DrawingResult result;
    const int nv = static_cast<int>(graph.position.size());
    std::vector<char> isFree(graph.position.size(), 0);
    for (int v = 0; v < nv && v < static_cast<int>(graph.free.size()); ++v) isFree[v] = graph.free[v] != 0;
    // Input no system can be built from is rejected outright.
    for (const AngleEdge& e : graph.edges)
        if (e.from < 0 || e.to < 0 || e.from >= nv || e.to >= nv || !std::isfinite(e.angle) ||
            !std::isfinite(e.minLength) || !std::isfinite(e.maxLength))
            return result;
    for (int v = 0; v < nv; ++v)
        if (!isFree[v] && !finite(graph.position[v])) return result;

    std::vector<vec2> pos = graph.position;
    std::vector<char> moved(graph.position.size(), 0);
    for (int i = 0; i < settings.proposals; ++i) {
        System s;
        build(graph, isFree, s);
        ++result.systems;
        if (s.consistent) {
            const int samples = s.kernel.cols() == 0 ? std::min(settings.samples, 1) : settings.samples;
            for (int j = 0; j < samples; ++j) {
                ++result.samples;
                sample(graph, settings, s, rng, pos);
                if (acceptable(graph, settings, s, pos, moved)) {
                    result.accepted = true;
                    result.moved = s.freeVertices;
                    for (int v : s.freeVertices) result.position.push_back(pos[v]);
                    return result;
                }
            }
        }
        if (i + 1 == settings.proposals) break;
        // Free a fixed end of an edge of E (OM-33: a neighbour of a free
        // vertex, or an end of a created edge).
        std::vector<int> candidates;
        for (int e : s.edges)
            for (int v : {graph.edges[e].from, graph.edges[e].to})
                if (!isFree[v]) candidates.push_back(v);
        if (candidates.empty()) break;
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        isFree[candidates[rng.below(candidates.size())]] = 1;
    }
    return result;
}

}  // namespace g2d::rt
