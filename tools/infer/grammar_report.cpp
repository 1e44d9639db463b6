#include "infer/grammar_report.hpp"

#include <cstdio>

namespace g2d::infer {
namespace {

std::string area(const LabelledExample& ex, int a) {
    return a < 0 ? std::string("none") : ex.shape.areas[static_cast<std::size_t>(a)].name;
}

}  // namespace

std::string graphText(const LabelledExample& ex, const InferredGrammar& g, int graph) {
    const HierarchyGraph& h = g.hierarchy[static_cast<std::size_t>(graph)].graph;
    if (h.isEdgeGraph()) return "edge " + boundaryString(ex, h.boundary);
    return boundaryString(ex, h.boundary) + " (" + std::to_string(h.vertexCount()) + (h.vertexCount() == 1 ? " vertex)" : " vertices)");
}

InferenceCounts countInference(const LabelledExample& ex, const InferredGrammar& g) {
    InferenceCounts c;
    c.vertices = static_cast<int>(ex.shape.vertices.size());
    c.edges = static_cast<int>(ex.shape.edges.size());
    c.labels = static_cast<int>(ex.labels.size());
    c.primitives = static_cast<int>(ex.primitives.size());
    c.snappedEdges = ex.snappedEdges;
    for (std::size_t i = static_cast<std::size_t>(g.edgeGraphs); i < g.hierarchy.size(); ++i) {
        ++c.graphs;
        switch (g.hierarchy[i].state) {
            case GraphState::Active: ++c.active; break;
            case GraphState::Reduced: ++c.reduced; break;
            case GraphState::Pruned: ++c.pruned; break;
            case GraphState::LeftOver: ++c.leftOver; break;
        }
    }
    c.starters = g.starters();
    c.rules = static_cast<int>(g.rules.size()) - c.starters;
    return c;
}

std::string describeGrammar(const LabelledExample& ex, const InferredGrammar& g) {
    const InferenceCounts c = countInference(ex, g);
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "example: %s (%d vertices, %d edges)\n", ex.shape.name.c_str(), c.vertices, c.edges);
    out += line;
    std::snprintf(line, sizeof line, "edge labels: %d%s\n", c.labels,
                  c.snappedEdges > 0 ? (" (" + std::to_string(c.snappedEdges) + " edges snapped onto a shared direction)").c_str() : "");
    out += line;
    for (std::size_t l = 0; l < ex.labels.size(); ++l) {
        const EdgeLabel& e = ex.labels[l];
        std::snprintf(line, sizeof line, "  %zu: %s at %g°, left %s, right %s, length %g to %g, %zu in the example\n", l,
                      ex.shape.brushes[static_cast<std::size_t>(e.brush)].name.c_str(), e.theta, area(ex, e.left).c_str(),
                      area(ex, e.right).c_str(), e.minLength, e.maxLength, e.edges.size());
        out += line;
    }
    out += "primitives: " + std::to_string(c.primitives) + "\n";
    for (std::size_t p = 0; p < ex.primitives.size(); ++p)
        out += "  P" + std::to_string(p) + ": " + boundaryString(ex, g.hierarchy[static_cast<std::size_t>(g.primitiveGraph[p])].graph.boundary) +
               " (" + std::to_string(ex.primitives[p].vertices.size()) + " in the example)\n";
    std::snprintf(line, sizeof line, "hierarchy: %d graphs (%d active, %d reduced, %d pruned, %d left over)\n", c.graphs, c.active,
                  c.reduced, c.pruned, c.leftOver);
    out += line;
    out += "rules: " + std::to_string(c.rules) + ", starter rules: " + std::to_string(c.starters) + "\n";
    for (std::size_t r = 0; r < g.rules.size(); ++r) {
        const InferredRule& rule = g.rules[r];
        out += "  " + std::to_string(r) + ": " + graphText(ex, g, rule.left) + " <->";
        if (rule.starter()) out += " nothing";
        for (std::size_t k = 0; k < rule.right.size(); ++k) out += (k ? " | " : " ") + graphText(ex, g, rule.right[k].graph);
        out += rule.restructures ? "  (restructures, §5.4)\n" : "\n";
    }
    if (c.pruned > 0)
        out += "note: " + std::to_string(c.pruned) +
               " graphs turning more than 360° between two half-edges were not grown (§5.7); the grammar lacks rules only "
               "if one of them has a complete descendant\n";
    if (c.leftOver > 0)
        out += "warning: the grammar may be incomplete: " + std::to_string(c.leftOver) +
               " graphs were left over at the hierarchy's limits (§5.7)\n";
    return out;
}

std::string inferenceStatsJson(const InferenceCounts& c, double milliseconds) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "{\"vertices\": %d, \"edges\": %d, \"labels\": %d, \"primitives\": %d, \"snapped_edges\": %d, \"graphs\": %d, "
                  "\"active\": %d, \"reduced\": %d, \"pruned\": %d, \"left_over\": %d, \"rules\": %d, \"starters\": %d, "
                  "\"milliseconds\": %.3f}\n",
                  c.vertices, c.edges, c.labels, c.primitives, c.snappedEdges, c.graphs, c.active, c.reduced, c.pruned, c.leftOver,
                  c.rules, c.starters, milliseconds);
    return buf;
}

}  // namespace g2d::infer
