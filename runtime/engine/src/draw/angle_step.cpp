#include "g2d/angle_step.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "g2d/spatial_grid.hpp"

namespace g2d::rt {

namespace {

Aabb boxOf(vec2 a, vec2 b) { return {vec3(std::min(a.x, b.x), std::min(a.y, b.y), 0), vec3(std::max(a.x, b.x), std::max(a.y, b.y), 0)}; }
bool same(const Aabb& p, const Aabb& q) { return p.lo == q.lo && p.hi == q.hi; }

}  // namespace

// The graph's edges and isolated nodes in uniform grids, kept up to date
// after each commit; for one proposal, the ones outside its part.
class AngleStep::Index : public FixedSurroundings {
public:
    Index(const Graph& g, double cell) : edges_(cell), points_(cell) {
        for (EdgeId e = 0; e < g.edgeCapacity(); ++e)
            if (g.edgeAlive(e)) upsertEdge(g, e);
        for (NodeId n = 0; n < g.nodeCapacity(); ++n)
            if (g.nodeAlive(n) && g.degree(n) == 0) upsertPoint(g, n);
    }

    // After a commit: `gone` the edges the application deleted (or rewired), g's change list the rest.
    void follow(const Graph& g, const std::vector<EdgeId>& gone) {
        for (EdgeId e : gone) {
            dropEdge(e);
            if (g.edgeAlive(e)) upsertEdge(g, e);
        }
        for (NodeId n : g.changedNodes()) {
            if (!g.nodeAlive(n)) {
                dropPoint(n);
                continue;
            }
            for (EdgeId e : g.incident(n)) upsertEdge(g, e);
            if (g.degree(n) == 0) upsertPoint(g, n);
            else dropPoint(n);
        }
    }

    // The proposal being drawn: what is deleted, which edges are the part's, and the host -> vertex map.
    void setPart(const Graph& g, const std::vector<char>& deletedNode, const std::vector<char>& deletedEdge, const std::vector<char>& partEdge,
                 const std::vector<int>& vertexOf) {
        g_ = &g;
        deletedNode_ = &deletedNode;
        deletedEdge_ = &deletedEdge;
        partEdge_ = &partEdge;
        vertexOf_ = &vertexOf;
    }

    void near(vec2 lo, vec2 hi, std::vector<FixedSegment>& out) const override {
        const Aabb box{vec3(lo.x, lo.y, 0), vec3(hi.x, hi.y, 0)};
        edges_.overlapping(box, ids_);
        for (std::uint32_t e : ids_) {
            const NodeId s = g_->source(e), t = g_->target(e);
            if ((*deletedEdge_)[e] || (*partEdge_)[e] || (*deletedNode_)[s] || (*deletedNode_)[t]) continue;
            out.push_back({g_->pos(s), g_->pos(t), (*vertexOf_)[s], (*vertexOf_)[t]});
        }
        points_.overlapping(box, ids_);
        for (std::uint32_t n : ids_)
            if (!(*deletedNode_)[n] && (*vertexOf_)[n] < 0) out.push_back({g_->pos(n), g_->pos(n), -1, -1});
    }

private:
    void upsertEdge(const Graph& g, EdgeId e) {
        const Aabb box = boxOf(g.pos(g.source(e)), g.pos(g.target(e)));
        if (e < edgeIn_.size() && edgeIn_[e]) {
            if (same(edgeBox_[e], box)) return;
            edges_.remove(e, edgeBox_[e]);
        }
        if (e >= edgeIn_.size()) edgeIn_.resize(e + 1 + e / 2, 0), edgeBox_.resize(edgeIn_.size());
        edges_.insert(e, box);
        edgeIn_[e] = 1;
        edgeBox_[e] = box;
    }
    void dropEdge(EdgeId e) {
        if (e >= edgeIn_.size() || !edgeIn_[e]) return;
        edges_.remove(e, edgeBox_[e]);
        edgeIn_[e] = 0;
    }
    void upsertPoint(const Graph& g, NodeId n) {
        dropPoint(n);
        if (n >= pointIn_.size()) pointIn_.resize(n + 1 + n / 2, 0), pointBox_.resize(pointIn_.size());
        pointBox_[n] = boxOf(g.pos(n), g.pos(n));
        points_.insert(n, pointBox_[n]);
        pointIn_[n] = 1;
    }
    void dropPoint(NodeId n) {
        if (n >= pointIn_.size() || !pointIn_[n]) return;
        points_.remove(n, pointBox_[n]);
        pointIn_[n] = 0;
    }

    SpatialBoxGrid edges_, points_;
    std::vector<Aabb> edgeBox_, pointBox_;
    std::vector<char> edgeIn_, pointIn_;
    const Graph* g_ = nullptr;
    const std::vector<char>* deletedNode_ = nullptr;
    const std::vector<char>* deletedEdge_ = nullptr;
    const std::vector<char>* partEdge_ = nullptr;
    const std::vector<int>* vertexOf_ = nullptr;
    mutable std::vector<std::uint32_t> ids_;
};

AngleEdge AngleStep::edgeOf(const AngleLayoutSpec& spec, int kind, int from, int to) const {
    const EdgeGeometry& e = spec.kinds[static_cast<std::size_t>(kind)];
    return AngleEdge{from, to, e.angle, e.minLength, e.maxLength, e.left, e.right, e.unit};
}

void AngleStep::markDeleted(const Graph& g, const DaughterShape& shape, Match m) {
    if (deletedNode_.size() < g.nodeCapacity()) deletedNode_.resize(g.nodeCapacity(), 0), index_.resize(g.nodeCapacity(), -1);
    if (deletedEdge_.size() < g.edgeCapacity()) deletedEdge_.resize(g.edgeCapacity(), 0), inPart_.resize(g.edgeCapacity(), 0);
    goneNodes_.clear();
    goneEdges_.clear();
    for (int p : shape.deletedNodes) goneNodes_.push_back(m.nodes[p]);
    for (int p : shape.deletedEdges) goneEdges_.push_back(m.edges[p]);
    for (NodeId n : goneNodes_)
        for (EdgeId e : g.incident(n)) goneEdges_.push_back(e);
    for (NodeId n : goneNodes_) deletedNode_[n] = 1;
    for (EdgeId e : goneEdges_) deletedEdge_[e] = 1;
}

void AngleStep::unmarkDeleted() {
    for (NodeId n : goneNodes_) deletedNode_[n] = 0;
    for (EdgeId e : goneEdges_) deletedEdge_[e] = 0;
    for (EdgeId e : partEdges_) inPart_[e] = 0;
    partEdges_.clear();
    for (NodeId h : host_)
        if (h != kNoId) index_[h] = -1;
}

// New nodes start where the deleted ones were (their mean), else at the canvas's centre.
namespace {
vec2 firstGuess(const Graph& g, const std::vector<NodeId>& gone, const AngleLayoutSpec& spec) {
    if (gone.empty()) return (spec.settings.canvasLo + spec.settings.canvasHi) * 0.5;
    vec2 sum{0, 0};
    for (NodeId n : gone) sum = sum + g.pos(n);
    return sum * (1.0 / static_cast<double>(gone.size()));
}
}  // namespace

// The fixed vertices (host nodes, ascending), then the new ones, free, where the deleted ones were.
void AngleStep::addVertices(const Graph& g, const std::vector<NodeId>& fixed, const DaughterShape& shape, const AngleLayoutSpec& spec,
                            AngleGraph& ag) {
    for (NodeId n : fixed) {
        index_[n] = static_cast<int>(host_.size());
        host_.push_back(n);
        ag.position.push_back(g.pos(n));
        ag.free.push_back(0);
    }
    firstNew_ = static_cast<int>(host_.size());
    const vec2 guess = firstGuess(g, goneNodes_, spec);
    for (int k = 0; k < shape.newNodes; ++k) {
        host_.push_back(kNoId);
        ag.position.push_back(guess);
        ag.free.push_back(1);
    }
}

void AngleStep::buildWhole(const Graph& g, const DaughterShape& shape, Match m, const AngleLayoutSpec& spec, AngleGraph& ag) {
    // The graph after the change: the surviving nodes (fixed), then the new ones (free).
    std::vector<NodeId> fixed;
    for (NodeId n = 0; n < g.nodeCapacity(); ++n)
        if (g.nodeAlive(n) && !deletedNode_[n]) fixed.push_back(n);
    addVertices(g, fixed, shape, spec, ag);
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e) {
        if (!g.edgeAlive(e) || deletedEdge_[e]) continue;
        const int s = index_[g.source(e)], t = index_[g.target(e)];
        if (s < 0 || t < 0) continue;   // at a deleted node: goes with it
        ag.edges.push_back(edgeOf(spec, g.edgeKind(e), s, t));
        ag.created.push_back(0);
    }
    (void)m;
}

void AngleStep::buildPart(const Graph& g, const DaughterShape& shape, Match m, const AngleLayoutSpec& spec, AngleGraph& ag) {
    // The core: host nodes within I - 2 edges of the created edges' host
    // ends (the last vertex the step may free lies there; its edges are the
    // part's); the part's vertices: the core and its neighbours.
    std::vector<NodeId> core;
    for (const auto& e : shape.newEdges)
        for (int end : {e.src, e.dst})
            if (end >= 0) core.push_back(m.nodes[end]);
    std::sort(core.begin(), core.end());
    core.erase(std::unique(core.begin(), core.end()), core.end());
    const int reach = spec.settings.proposals - 2;
    // index_ marks visits while the part is gathered (-2: core, -3: neighbour), then holds vertices.
    std::deque<std::pair<NodeId, int>> open;
    std::vector<NodeId> seen;
    for (NodeId n : core) {
        index_[n] = -2;
        seen.push_back(n);
        if (reach >= 0) open.push_back({n, 0});
    }
    while (!open.empty()) {
        const auto [n, d] = open.front();
        open.pop_front();
        for (EdgeId e : g.incident(n)) {
            if (deletedEdge_[e]) continue;
            const NodeId w = g.source(e) == n ? g.target(e) : g.source(e);
            if (deletedNode_[w]) continue;
            if (index_[w] == -1) {
                index_[w] = d + 1 <= reach ? -2 : -3;
                seen.push_back(w);
                if (d + 1 <= reach) open.push_back({w, d + 1});
            }
            if (!inPart_[e]) {
                inPart_[e] = 1;
                partEdges_.push_back(e);
            }
        }
    }
    std::sort(seen.begin(), seen.end());
    addVertices(g, seen, shape, spec, ag);
    std::sort(partEdges_.begin(), partEdges_.end());
    for (EdgeId e : partEdges_) {
        ag.edges.push_back(edgeOf(spec, g.edgeKind(e), index_[g.source(e)], index_[g.target(e)]));
        ag.created.push_back(0);
    }
    if (!grid_) {
        double cell = 0;
        for (const EdgeGeometry& k : spec.kinds)
            if (k.given) cell = std::max(cell, (k.minLength + k.maxLength) / 4);
        const vec2 span = spec.settings.canvasHi - spec.settings.canvasLo;
        cell = std::max(cell, std::max(span.x, span.y) / 4096);
        grid_ = std::make_shared<Index>(g, cell > 0 && std::isfinite(cell) ? cell : 1.0);
    }
    grid_->setPart(g, deletedNode_, deletedEdge_, inPart_, index_);
    ag.surroundings = grid_.get();
}

bool AngleStep::propose(const Graph& g, const DaughterShape& shape, Match m, const AngleLayoutSpec& spec, Rng& rng) {
    markDeleted(g, shape, m);
    host_.clear();
    AngleGraph ag;
    DrawingSettings settings = spec.settings;
    settings.consistentAreas = std::any_of(spec.kinds.begin(), spec.kinds.end(),
                                           [](const EdgeGeometry& k) { return k.left >= 0 || k.right >= 0; });
    // Areas are tested over the whole drawing (areasConsistent): the part alone cannot tell.
    if (whole_ || settings.consistentAreas) buildWhole(g, shape, m, spec, ag);
    else buildPart(g, shape, m, spec, ag);
    auto vertex = [&](int end) { return end >= 0 ? index_[m.nodes[end]] : firstNew_ + (-1 - end); };
    for (const auto& e : shape.newEdges) {
        ag.edges.push_back(edgeOf(spec, e.kind, vertex(e.src), vertex(e.dst)));
        ag.created.push_back(1);
    }
    result_ = drawAngleGraph(ag, settings, rng);
    if (!result_.accepted) ++rejected_;
    unmarkDeleted();
    return result_.accepted;
}

void AngleStep::place(Graph& g, NodeId newNodesFrom) {
    for (std::size_t i = 0; i < result_.moved.size(); ++i) {
        const int v = result_.moved[i];
        const NodeId n = v >= firstNew_ ? newNodesFrom + static_cast<NodeId>(v - firstNew_) : host_[static_cast<std::size_t>(v)];
        g.setPos(n, result_.position[i]);
    }
    if (grid_) grid_->follow(g, goneEdges_);
}

}  // namespace g2d::rt
