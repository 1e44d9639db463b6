#include "g2d/drawn_faces.hpp"

#include "g2d/angle_faces.hpp"

namespace g2d::rt {

std::size_t addDrawnFaces(Graph& g, RuleSet& rules, const AngleLayoutSpec& spec, long long age) {
    std::vector<int> index(g.nodeCapacity(), -1);
    std::vector<NodeId> host;
    std::vector<vec2> position;
    for (NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        index[n] = static_cast<int>(host.size());
        host.push_back(n);
        position.push_back(g.pos(n));
    }
    std::vector<SidedEdge> edges;
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e) {
        if (!g.edgeAlive(e)) continue;
        const EdgeGeometry& k = spec.kinds[static_cast<std::size_t>(g.edgeKind(e))];
        edges.push_back(SidedEdge{index[g.source(e)], index[g.target(e)], k.left, k.right});
    }
    const std::vector<TracedFace> faces = traceFaces(position, edges);
    std::vector<NodeId> corners;
    for (const TracedFace& f : faces) {
        corners.clear();
        for (int v : f.corners) corners.push_back(host[static_cast<std::size_t>(v)]);
        const FaceId id = rules.addFaceWithDefaults(g, f.kind, corners, age);
        if (f.holes.empty()) continue;
        std::vector<std::vector<NodeId>> holes;
        for (const std::vector<int>& ring : f.holes) {
            holes.emplace_back();
            for (int v : ring) holes.back().push_back(host[static_cast<std::size_t>(v)]);
        }
        g.setFaceHoles(id, std::move(holes));
    }
    return faces.size();
}

}  // namespace g2d::rt
