#include "infer/hierarchy_graph.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace g2d::infer {
namespace {

double slotDirection(const LabelledExample& ex, const HierarchyGraph& g, int v, int slot) {
    const Primitive& p = ex.primitives[static_cast<std::size_t>(g.type[static_cast<std::size_t>(v)])];
    return ex.direction(p.halves[static_cast<std::size_t>(slot)]);
}
int slotHalf(const LabelledExample& ex, const HierarchyGraph& g, int v, int slot) {
    return ex.primitives[static_cast<std::size_t>(g.type[static_cast<std::size_t>(v)])].halves[static_cast<std::size_t>(slot)];
}
// (b - a) into (0, 360]: the counter-clockwise sweep from a to b.
double sweep(double a, double b) {
    double d = std::fmod(b - a, 360.0);
    if (d <= 0) d += 360.0;
    return d;
}

}  // namespace

int HierarchyGraph::gluedEdges() const {
    int n = 0;
    for (const auto& slots : links)
        for (const Link& l : slots) n += l.vertex >= 0 ? 1 : 0;
    return n / 2;
}

HierarchyGraph primitiveGraph(const LabelledExample& ex, int primitive) {
    HierarchyGraph g;
    g.type = {primitive};
    g.links = {std::vector<Link>(ex.primitives[static_cast<std::size_t>(primitive)].halves.size())};
    g.boundary = walkBoundary(ex, g);
    return g;
}

HierarchyGraph edgeGraph(const LabelledExample&, int edgeLabel) {
    HierarchyGraph g;
    g.edgeLabel = edgeLabel;
    // Out along a (W = θ), round its end and back along ā (W = θ + 180 = φ(ā) + 360).
    g.boundary = {BoundaryEntry{halfLabel(edgeLabel, false), -1, -1, 0}, BoundaryEntry{halfLabel(edgeLabel, true), -1, -1, 1}};
    return g;
}

std::vector<BoundaryEntry> walkBoundary(const LabelledExample& ex, const HierarchyGraph& g) {
    std::vector<BoundaryEntry> out;
    int v0 = -1, s0 = -1;
    for (int v = 0; v < g.vertexCount() && v0 < 0; ++v)
        for (int s = 0; s < static_cast<int>(g.links[static_cast<std::size_t>(v)].size()); ++s)
            if (g.links[static_cast<std::size_t>(v)][static_cast<std::size_t>(s)].vertex < 0) {
                v0 = v;
                s0 = s;
                break;
            }
    if (v0 < 0) return out;
    // Leaving along (v, s) with heading w; an open slot is an entry, and the
    // walk comes back along it; then it leaves along the next slot
    // counter-clockwise, turning by the sweep between the two minus 180°.
    int v = v0, s = s0;
    const double w0 = slotDirection(ex, g, v0, s0);
    double w = w0;
    const std::size_t limit = 4 * static_cast<std::size_t>(g.gluedEdges() + 1) + 4 * g.links.size() + 8;
    for (std::size_t step = 0;; ++step) {
        if (step > 8 * limit) throw std::logic_error("walkBoundary: the walk does not close");
        const Link& l = g.links[static_cast<std::size_t>(v)][static_cast<std::size_t>(s)];
        int arriveVertex = v, arriveSlot = s;
        if (l.vertex < 0) {
            const double phi = slotDirection(ex, g, v, s);
            out.push_back({slotHalf(ex, g, v, s), v, s, static_cast<int>(std::lround((w - phi) / 360.0))});
        } else {
            arriveVertex = l.vertex;
            arriveSlot = l.slot;
        }
        const int degree = static_cast<int>(g.links[static_cast<std::size_t>(arriveVertex)].size());
        const int next = (arriveSlot + 1) % degree;
        w += sweep(slotDirection(ex, g, arriveVertex, arriveSlot), slotDirection(ex, g, arriveVertex, next)) - 180.0 +
             (l.vertex < 0 ? 180.0 : 0.0);
        v = arriveVertex;
        s = next;
        if (v == v0 && s == s0) break;
    }
    if (std::fabs(w - w0 - 360.0) > 1e-6) throw std::logic_error("walkBoundary: the boundary does not turn once");
    return out;
}

HierarchyGraph branchGlue(const LabelledExample& ex, const HierarchyGraph& g, int entry, int primitive, int slot) {
    HierarchyGraph out = g;
    const BoundaryEntry& e = g.boundary[static_cast<std::size_t>(entry)];
    const int nv = out.vertexCount();
    out.type.push_back(primitive);
    out.links.emplace_back(ex.primitives[static_cast<std::size_t>(primitive)].halves.size());
    out.links[static_cast<std::size_t>(e.vertex)][static_cast<std::size_t>(e.slot)] = {nv, slot};
    out.links[static_cast<std::size_t>(nv)][static_cast<std::size_t>(slot)] = {e.vertex, e.slot};
    out.boundary = walkBoundary(ex, out);
    return out;
}

bool loopGlue(const LabelledExample& ex, const HierarchyGraph& g, int i, HierarchyGraph& out) {
    const int m = static_cast<int>(g.boundary.size());
    if (m < 2 || g.isEdgeGraph()) return false;
    const int j = (i + 1) % m;
    const BoundaryEntry& a = g.boundary[static_cast<std::size_t>(i)];
    const BoundaryEntry& b = g.boundary[static_cast<std::size_t>(j)];
    if (b.half != complement(a.half) || a.vertex == b.vertex) return false;
    // W(b) − W(a) = −180°: a then ā with no turn between, or ā ∨ a.
    const int wb = b.wind + (j == 0 ? 1 : 0);
    if (wb != a.wind - (barred(a.half) ? 1 : 0)) return false;
    for (const Link& l : g.links[static_cast<std::size_t>(a.vertex)])
        if (l.vertex == b.vertex) return false;
    out = g;
    out.links[static_cast<std::size_t>(a.vertex)][static_cast<std::size_t>(a.slot)] = {b.vertex, b.slot};
    out.links[static_cast<std::size_t>(b.vertex)][static_cast<std::size_t>(b.slot)] = {a.vertex, a.slot};
    ++out.loops;
    out.boundary = walkBoundary(ex, out);
    return true;
}

std::string canonicalCode(const HierarchyGraph& g) {
    if (g.isEdgeGraph()) return "e" + std::to_string(g.edgeLabel);
    const int minType = *std::min_element(g.type.begin(), g.type.end());
    std::vector<int> best;
    std::vector<int> index(g.type.size()), order;
    for (int start = 0; start < g.vertexCount(); ++start) {
        if (g.type[static_cast<std::size_t>(start)] != minType) continue;
        std::fill(index.begin(), index.end(), -1);
        order.assign(1, start);
        index[static_cast<std::size_t>(start)] = 0;
        std::vector<int> code;
        for (std::size_t k = 0; k < order.size(); ++k) {
            const int v = order[k];
            code.push_back(g.type[static_cast<std::size_t>(v)]);
            for (const Link& l : g.links[static_cast<std::size_t>(v)]) {
                if (l.vertex < 0) {
                    code.push_back(-1);
                    continue;
                }
                if (index[static_cast<std::size_t>(l.vertex)] < 0) {
                    index[static_cast<std::size_t>(l.vertex)] = static_cast<int>(order.size());
                    order.push_back(l.vertex);
                }
                code.push_back(index[static_cast<std::size_t>(l.vertex)]);
            }
        }
        if (best.empty() || code < best) best = code;
    }
    std::string key;
    key.reserve(best.size() * 3);
    for (int c : best) {
        key += std::to_string(c);
        key += ',';
    }
    return key;
}

bool occursIn(const HierarchyGraph& pattern, const HierarchyGraph& host) { return !findOccurrence(pattern, host).empty(); }

std::vector<int> findOccurrence(const HierarchyGraph& pattern, const HierarchyGraph& host) {
    if (pattern.isEdgeGraph() || host.isEdgeGraph() || pattern.vertexCount() > host.vertexCount() || pattern.type.empty()) return {};
    const std::size_t n = pattern.type.size();
    std::vector<int> image(n), preimage(host.type.size());
    for (int anchor = 0; anchor < host.vertexCount(); ++anchor) {
        if (host.type[static_cast<std::size_t>(anchor)] != pattern.type[0]) continue;
        std::fill(image.begin(), image.end(), -1);
        std::fill(preimage.begin(), preimage.end(), -1);
        image[0] = anchor;
        preimage[static_cast<std::size_t>(anchor)] = 0;
        std::vector<int> todo{0};
        bool ok = true;
        while (ok && !todo.empty()) {
            const int v = todo.back();
            todo.pop_back();
            const auto& ps = pattern.links[static_cast<std::size_t>(v)];
            const auto& hs = host.links[static_cast<std::size_t>(image[static_cast<std::size_t>(v)])];
            for (std::size_t s = 0; s < ps.size() && ok; ++s) {
                if (ps[s].vertex < 0) continue;
                const Link h = hs[s];
                const int u = ps[s].vertex;
                if (h.vertex < 0 || h.slot != ps[s].slot || host.type[static_cast<std::size_t>(h.vertex)] != pattern.type[static_cast<std::size_t>(u)]) {
                    ok = false;
                } else if (image[static_cast<std::size_t>(u)] < 0) {
                    if (preimage[static_cast<std::size_t>(h.vertex)] >= 0) {
                        ok = false;
                    } else {
                        image[static_cast<std::size_t>(u)] = h.vertex;
                        preimage[static_cast<std::size_t>(h.vertex)] = u;
                        todo.push_back(u);
                    }
                } else if (image[static_cast<std::size_t>(u)] != h.vertex) {
                    ok = false;
                }
            }
        }
        if (!ok) continue;
        // The interface: an open half of the pattern never leads back into its image.
        for (std::size_t v = 0; v < n && ok; ++v) {
            const auto& ps = pattern.links[v];
            const auto& hs = host.links[static_cast<std::size_t>(image[v])];
            for (std::size_t s = 0; s < ps.size() && ok; ++s)
                if (ps[s].vertex < 0 && hs[s].vertex >= 0 && preimage[static_cast<std::size_t>(hs[s].vertex)] >= 0) ok = false;
        }
        if (ok) return image;
    }
    return {};
}

std::string boundaryString(const LabelledExample&, const std::vector<BoundaryEntry>& boundary) {
    std::string out;
    auto turns = [&](int k) {
        for (; k > 0; --k) out += " ^";
        for (; k < 0; ++k) out += " v";
    };
    for (std::size_t i = 0; i < boundary.size(); ++i) {
        out += (out.empty() ? "" : " ") + std::to_string(edgeOfHalf(boundary[i].half)) + (barred(boundary[i].half) ? "'" : "");
        const int next = i + 1 < boundary.size() ? boundary[i + 1].wind : boundary[0].wind + 1;
        turns(next - boundary[i].wind);
    }
    if (boundary.empty()) out = "^";
    return out;
}

}  // namespace g2d::infer
