#include "g2d/drawing_cost.hpp"

#include <algorithm>
#include <cmath>

namespace g2d::rt {

KindCounts KindCounts::of(const Graph& g, std::size_t kinds) {
    KindCounts c(kinds);
    for (NodeId n = 0; n < g.nodeCapacity(); ++n)
        if (g.nodeAlive(n)) c.add(g.nodeKind(n), 1), c.add(kNodes, 1);
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) c.add(g.edgeKind(e), 1), c.add(kEdges, 1);
    return c;
}

void countChange(const Graph& g, const DaughterShape& shape, Match m, KindCounts& counts) {
    // Deleted edges: the named ones, and those at deleted nodes, each once.
    std::vector<EdgeId> gone;
    for (int p : shape.deletedEdges) gone.push_back(m.edges[p]);
    for (int p : shape.deletedNodes)
        for (EdgeId e : g.incident(m.nodes[p])) gone.push_back(e);
    std::sort(gone.begin(), gone.end());
    gone.erase(std::unique(gone.begin(), gone.end()), gone.end());
    for (EdgeId e : gone) counts.add(g.edgeKind(e), -1), counts.add(KindCounts::kEdges, -1);
    for (int p : shape.deletedNodes) counts.add(g.nodeKind(m.nodes[p]), -1), counts.add(KindCounts::kNodes, -1);
    for (int k : shape.newNodeKinds) counts.add(k, 1), counts.add(KindCounts::kNodes, 1);
    for (const auto& e : shape.newEdges) counts.add(e.kind, 1), counts.add(KindCounts::kEdges, 1);
}

bool metropolisAccepts(double delta, double temperature, Rng& rng) {
    if (!(delta > 0)) return true;
    return rng.unit() < std::exp(-delta / temperature);
}

}  // namespace g2d::rt
