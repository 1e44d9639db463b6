#pragma once
// What an inferred grammar's output must be (Merrell 2023 §3.3): locally
// similar to the example, each vertex's star (its half-edges: label, and
// whether the edge arrives) the star of the primitive its kind names. Shared
// by the structured inference fuzz target and the inference tests.
#include "g2d/graph.hpp"
#include "infer/labelled_example.hpp"
#include "ir/ir.hpp"

namespace g2d::fuzz {

struct InferredOutput {
    int vertices = 0;
    int pieces = 0;          // connected components
    int dissimilar = -1;     // a node whose star is not its primitive's, or -1
};

// `graph` is a run of the grammar g2d infer wrote for `ex` (kinds P<i> and L<j>).
InferredOutput measureInferredOutput(const infer::LabelledExample& ex, const ir::Program& program, const rt::Graph& graph);

}  // namespace g2d::fuzz
