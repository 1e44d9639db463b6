#pragma once
// Merrell 2023 §5: a graph grammar from the primitives. Algorithm 1 builds
// the graph hierarchy from the simplest graphs up; every graph that a rule
// can simplify is reduced and not grown further; a complete graph no rule
// reduces gets a starter rule (§5.3.1). Algorithm 2 (matching_groups.hpp)
// finds a rule's right side by matching boundary strings.
#include <cstdint>
#include <string>
#include <vector>

#include "infer/hierarchy_graph.hpp"

namespace g2d::infer {

struct InferOptions {
    int maxGeneration = 20;      // §5.7: graphs of more glues are left over (the author's app: 20)
    int maxHalfEdges = 16;       // §5.7: graphs with more open half-edges are left over
    int maxGraphs = 3000;        // the hierarchy stops growing here; what is queued is left over
    bool noLoops = false;        // Appendix A: no loop glue, so rules make no new cycles
};

enum class GraphState {
    Active,     // in the hierarchy, grown by gluing
    Reduced,    // the left side of a rule, or contains one: not grown
    Pruned,     // has no complete descendant (§5.6): not grown
    LeftOver,   // beyond a limit (§5.7): not grown, and may need a rule the grammar lacks
};

struct RulePiece {
    int graph = -1;                  // a hierarchy graph (an edge graph, a primitive, ...)
    std::vector<int> leftEntry;      // per boundary entry of the piece, the left side's entry it replaces
};

struct InferredRule {
    int left = -1;                   // the more complex graph L
    std::vector<RulePiece> right;    // the simpler graphs spliced together (empty: a starter rule, L <-> ∅)
    bool restructures = false;       // a piece contains L (§5.4)
    bool starter() const { return right.empty(); }
};

struct HierarchyEntry {
    HierarchyGraph graph;
    GraphState state = GraphState::Active;
    int order = 0;                   // insertion order: among equals, earlier is simpler
    int reducedBy = -1;              // the rule it is the left side of, or contains
    int generation = 0;              // graph.generation(), kept
    std::vector<int> halves;         // its boundary's half-edge labels, sorted (a multiset)
    std::uint64_t halfMask = 0;      // bit (half % 64) for each: a quick subset test
};

struct InferredGrammar {
    std::vector<HierarchyEntry> hierarchy;   // edge graphs first, then primitives, then the rest as found
    std::vector<InferredRule> rules;         // in the order found
    int edgeGraphs = 0;                      // hierarchy[0, edgeGraphs) are the edge graphs
    std::vector<int> primitiveGraph;         // per primitive: its hierarchy graph
    int leftOver() const;
    int starters() const;
};

InferredGrammar inferGrammar(const LabelledExample& ex, const InferOptions& options = {});

}  // namespace g2d::infer
