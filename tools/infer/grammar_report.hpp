#pragma once
// What `g2d infer` tells a person about an inferred grammar: the labels,
// primitives and rules as the paper writes them, and the numbers of its
// Table 1 (primitives, hierarchy graphs, rules, time).
#include <string>

#include "infer/grammar_inference.hpp"

namespace g2d::infer {

struct InferenceCounts {
    int vertices = 0, edges = 0, labels = 0, primitives = 0, snappedEdges = 0;
    int graphs = 0, active = 0, reduced = 0, pruned = 0, leftOver = 0;
    int rules = 0, starters = 0;
};

InferenceCounts countInference(const LabelledExample& ex, const InferredGrammar& g);
// A hierarchy graph as the rules are listed: "edge a" or its boundary string and vertex count.
std::string graphText(const LabelledExample& ex, const InferredGrammar& g, int graph);
std::string describeGrammar(const LabelledExample& ex, const InferredGrammar& g);
// One JSON object (the counts and the time in milliseconds).
std::string inferenceStatsJson(const InferenceCounts& c, double milliseconds);

}  // namespace g2d::infer
