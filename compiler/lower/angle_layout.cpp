#include "lower/angle_layout.hpp"

namespace g2d::lower {

std::optional<rt::AngleLayoutSpec> angleLayoutSpec(const ir::Program& prog) {
    if (!prog.angleLayout) return std::nullopt;
    const ir::AngleLayout& l = *prog.angleLayout;
    rt::AngleLayoutSpec spec;
    spec.settings.proposals = l.proposals;
    spec.settings.samples = l.samples;
    spec.connected = l.connected;
    spec.bendSegment = l.bendSegment;
    spec.bendSmooth = l.bendSmooth;
    if (l.clearance > 0) spec.settings.separation = l.clearance;
    spec.settings.canvasLo = rt::vec2(l.canvasMin[0], l.canvasMin[1]);
    spec.settings.canvasHi = rt::vec2(l.canvasMax[0], l.canvasMax[1]);
    for (const auto& k : prog.kinds) {
        rt::EdgeGeometry e;
        if (k.layout)
            e = rt::EdgeGeometry{true, k.layout->angle, k.layout->minLength, k.layout->maxLength, k.layout->left, k.layout->right, k.layout->unit,
                                 k.layout->bend};
        spec.kinds.push_back(e);
    }
    return spec;
}

rt::DaughterShape daughterShape(const ir::Rule& rule, std::size_t d) {
    const ir::Daughter& dg = rule.daughters[d];
    rt::DaughterShape out;
    out.deletedNodes = dg.deletedNodes;
    out.deletedEdges = dg.deletedEdges;
    // Daughter node -> pattern node (kept) or -1 - k (the k-th new one, in creation order).
    std::vector<int> end(dg.nodes.size());
    for (std::size_t i = 0; i < dg.nodes.size(); ++i) {
        end[i] = dg.nodes[i].motherNode >= 0 ? dg.nodes[i].motherNode : -1 - out.newNodes++;
        if (dg.nodes[i].motherNode < 0) out.newNodeKinds.push_back(dg.nodes[i].kind);
    }
    for (const auto& e : dg.edges) {
        if (e.motherEdge >= 0) {
            if (!ir::keptEdgeRewired(rule, dg, e)) continue;
            out.deletedEdges.push_back(e.motherEdge);
        }
        out.newEdges.push_back(rt::DaughterShape::NewEdge{end[static_cast<std::size_t>(e.src)], end[static_cast<std::size_t>(e.dst)], e.kind});
    }
    return out;
}

}  // namespace g2d::lower
