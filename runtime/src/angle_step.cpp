#include "g2d/angle_step.hpp"

#include <algorithm>

namespace g2d::rt {

bool AngleStep::propose(const Graph& g, const DaughterShape& shape, Match m, const AngleLayoutSpec& spec, Rng& rng) {
    deletedNode_.assign(g.nodeCapacity(), 0);
    deletedEdge_.assign(g.edgeCapacity(), 0);
    for (int p : shape.deletedNodes) deletedNode_[m.nodes[p]] = 1;
    for (int p : shape.deletedEdges) deletedEdge_[m.edges[p]] = 1;

    // The graph after the change: the surviving nodes (fixed), then the new ones (free).
    AngleGraph ag;
    index_.assign(g.nodeCapacity(), -1);
    host_.clear();
    vec2 guess{0, 0};
    int guessed = 0;
    for (NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        if (deletedNode_[n]) {
            guess = guess + g.pos(n);
            ++guessed;
            continue;
        }
        index_[n] = static_cast<int>(host_.size());
        host_.push_back(n);
        ag.position.push_back(g.pos(n));
        ag.free.push_back(0);
    }
    if (guessed == 0)
        guess = (spec.settings.canvasLo + spec.settings.canvasHi) * 0.5;
    else
        guess = guess * (1.0 / guessed);
    firstNew_ = static_cast<int>(host_.size());
    for (int k = 0; k < shape.newNodes; ++k) {
        host_.push_back(kNoId);
        ag.position.push_back(guess);
        ag.free.push_back(1);
    }
    auto edgeOf = [&](int kind, int from, int to) {
        const EdgeGeometry& e = spec.kinds[static_cast<std::size_t>(kind)];
        return AngleEdge{from, to, e.angle, e.minLength, e.maxLength, e.left, e.right};
    };
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e) {
        if (!g.edgeAlive(e) || deletedEdge_[e]) continue;
        const int s = index_[g.source(e)], t = index_[g.target(e)];
        if (s < 0 || t < 0) continue;   // at a deleted node: goes with it
        ag.edges.push_back(edgeOf(g.edgeKind(e), s, t));
        ag.created.push_back(0);
    }
    auto vertex = [&](int end) { return end >= 0 ? index_[m.nodes[end]] : firstNew_ + (-1 - end); };
    for (const auto& e : shape.newEdges) {
        ag.edges.push_back(edgeOf(e.kind, vertex(e.src), vertex(e.dst)));
        ag.created.push_back(1);
    }
    DrawingSettings settings = spec.settings;
    settings.consistentAreas = std::any_of(spec.kinds.begin(), spec.kinds.end(),
                                           [](const EdgeGeometry& k) { return k.left >= 0 || k.right >= 0; });
    result_ = drawAngleGraph(ag, settings, rng);
    if (!result_.accepted) ++rejected_;
    return result_.accepted;
}

void AngleStep::place(Graph& g, NodeId newNodesFrom) const {
    for (std::size_t i = 0; i < result_.moved.size(); ++i) {
        const int v = result_.moved[i];
        const NodeId n = v >= firstNew_ ? newNodesFrom + static_cast<NodeId>(v - firstNew_) : host_[static_cast<std::size_t>(v)];
        g.setPos(n, result_.position[i]);
    }
}

}  // namespace g2d::rt
