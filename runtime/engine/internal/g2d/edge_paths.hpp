#pragma once
// The drawn path of an edge or of a ring of nodes, bends included
// (Graph::edgeBend): what every writer draws, so all draw the same shape.
#include <span>
#include <vector>

#include "g2d/graph.hpp"

namespace g2d::rt {

// A point of a path: a node, or bend point `index` of edge `edge`.
struct PathPoint {
    NodeId node = kNoId;   // kNoId: a bend point
    EdgeId edge = kNoId;
    std::uint32_t index = 0;
};

// The edge the ring steps along from u to its next node v (one whose ends
// are u and v), and whether it runs v -> u; kNoId if none.
struct RingStep {
    EdgeId edge = kNoId;
    bool reversed = false;
};
RingStep ringStep(const Graph& g, NodeId u, NodeId v);

// Calls `f` for each point of the closed ring: each node, then the bend
// points of the edge to the next node, in the ring's direction.
template <class F>
void forEachRingPoint(const Graph& g, std::span<const NodeId> ring, F f) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
        f(PathPoint{ring[i]});
        if (!g.hasBends()) continue;
        const RingStep s = ringStep(g, ring[i], ring[(i + 1) % ring.size()]);
        if (s.edge == kNoId) continue;
        const auto bend = g.edgeBend(s.edge);
        for (std::size_t k = 0; k < bend.size(); ++k)
            f(PathPoint{kNoId, s.edge, static_cast<std::uint32_t>(s.reversed ? bend.size() - 1 - k : k)});
    }
}

// The positions of a ring of nodes with its edges' bends.
std::vector<vec2> bentRing(const Graph& g, std::span<const NodeId> ring);

}  // namespace g2d::rt
