#include "infer/rule_sides.hpp"

namespace g2d::infer {
namespace {

int interfaceNode(int k) { return -1 - k; }

// An edge between the ends holding `half` (at a) and its complement (at b).
SideEdge edgeFrom(int a, int half, int b) {
    return barred(half) ? SideEdge{b, a, edgeOfHalf(half)} : SideEdge{a, b, edgeOfHalf(half)};
}

// Appends g's vertices (numbered from base) and its glued edges, each pair of slots once.
void addGraph(const LabelledExample& ex, const HierarchyGraph& g, RuleSide& side) {
    const int base = static_cast<int>(side.primitive.size());
    for (int t : g.type) side.primitive.push_back(t);
    for (int v = 0; v < g.vertexCount(); ++v) {
        const auto& halves = ex.primitives[static_cast<std::size_t>(g.type[static_cast<std::size_t>(v)])].halves;
        const auto& links = g.links[static_cast<std::size_t>(v)];
        for (int s = 0; s < static_cast<int>(links.size()); ++s) {
            const Link l = links[static_cast<std::size_t>(s)];
            if (l.vertex < v || (l.vertex == v && l.slot < s)) continue;   // open, or met from the other end
            side.edges.push_back(edgeFrom(base + v, halves[static_cast<std::size_t>(s)], base + l.vertex));
        }
    }
}

}  // namespace

RuleSides ruleSides(const LabelledExample& ex, const InferredGrammar& grammar, const InferredRule& rule) {
    const HierarchyGraph& left = grammar.hierarchy[static_cast<std::size_t>(rule.left)].graph;
    RuleSides out;
    out.interface = static_cast<int>(left.boundary.size());
    addGraph(ex, left, out.left);
    for (int k = 0; k < out.interface; ++k) {
        const BoundaryEntry& e = left.boundary[static_cast<std::size_t>(k)];
        out.left.edges.push_back(edgeFrom(e.vertex, e.half, interfaceNode(k)));
    }
    // R: the pieces side by side, piece entry q taking the place of L's entry leftEntry[q].
    for (const RulePiece& piece : rule.right) {
        const HierarchyGraph& p = grammar.hierarchy[static_cast<std::size_t>(piece.graph)].graph;
        if (p.isEdgeGraph()) {   // a ∧ ā: one edge between the two interface nodes, each holding its entry's complement
            out.right.edges.push_back(
                edgeFrom(interfaceNode(piece.leftEntry[0]), complement(p.boundary[0].half), interfaceNode(piece.leftEntry[1])));
            continue;
        }
        const int base = static_cast<int>(out.right.primitive.size());
        addGraph(ex, p, out.right);
        for (std::size_t q = 0; q < p.boundary.size(); ++q)
            out.right.edges.push_back(edgeFrom(base + p.boundary[q].vertex, p.boundary[q].half, interfaceNode(piece.leftEntry[q])));
    }
    return out;
}

}  // namespace g2d::infer
