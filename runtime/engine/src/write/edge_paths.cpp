#include "g2d/edge_paths.hpp"

namespace g2d::rt {

RingStep ringStep(const Graph& g, NodeId u, NodeId v) {
    for (EdgeId e : g.incident(u)) {
        if (g.source(e) == u && g.target(e) == v) return {e, false};
        if (g.source(e) == v && g.target(e) == u) return {e, true};
    }
    return {};
}

std::vector<vec2> bentRing(const Graph& g, std::span<const NodeId> ring) {
    std::vector<vec2> out;
    out.reserve(ring.size());
    forEachRingPoint(g, ring, [&](const PathPoint& p) {
        out.push_back(p.node != kNoId ? g.pos(p.node) : g.edgeBend(p.edge)[p.index]);
    });
    return out;
}

}  // namespace g2d::rt
