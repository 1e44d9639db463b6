#pragma once
// A rule applied destructively (L -> its pieces) to a hierarchy graph, as a
// double pushout: the match's vertices are cut out and the pieces glued to
// the same interface half-edges. Inference uses it to follow the example
// itself down to graphs the grammar must start from.
#include <vector>

#include "infer/grammar_inference.hpp"

namespace g2d::infer {

// `image`: per vertex of the rule's left side, its host vertex (findOccurrence).
// The result's connected components, each with its boundary walked.
std::vector<HierarchyGraph> applyDestructively(const LabelledExample& ex, const InferredGrammar& grammar, const InferredRule& rule,
                                               const HierarchyGraph& host, const std::vector<int>& image);

// The connected components of a graph (vertices renumbered, boundaries walked).
std::vector<HierarchyGraph> components(const LabelledExample& ex, const HierarchyGraph& g);

}  // namespace g2d::infer
