#pragma once
// The two sides of one inferred rule as plain graphs, the form a `.g2d` rule
// writes them in: L with its boundary half-edges leading to interface nodes,
// and R assembled from the rule's pieces as applyDestructively glues them
// (rule_application.cpp). Interface node k stands for the half-edge across
// from L's boundary entry k, so it keeps its edge end from one side to the
// other; that is what makes the rule a double pushout.
#include <vector>

#include "infer/grammar_inference.hpp"

namespace g2d::infer {

// Vertex ends: >= 0 a vertex of the side, < 0 the interface node -1-k (k =
// index of L's boundary entry). Directed from the unbarred half's vertex to
// the barred one's, as the edge kinds are.
struct SideEdge {
    int from = 0, to = 0;
    int label = 0;
};

struct RuleSide {
    std::vector<int> primitive;     // per vertex
    std::vector<SideEdge> edges;
};

struct RuleSides {
    RuleSide left, right;
    int interface = 0;              // = L's boundary size (0 for a starter: L is complete, R empty)
};

RuleSides ruleSides(const LabelledExample& ex, const InferredGrammar& grammar, const InferredRule& rule);

}  // namespace g2d::infer
