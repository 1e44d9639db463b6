#pragma once
// An inferred grammar written as `.g2d` source (docs/infer.md, "Generation"):
// one node kind per primitive, one directed edge kind per edge label with its
// direction, lengths and areas for the `layout angles` drawing step, one face
// kind per area, and each rule L <-> R as two `dpo` rules (a starter as
// Start/Stop from and to nothing). Running it is Merrell's Algorithm 3.
#include <string>

#include "infer/grammar_inference.hpp"
#include "infer/rule_sides.hpp"

namespace g2d::infer {

struct WriterOptions {
    std::string source;     // the example's path, for the header comment
    int iterations = 0;     // the default of the `iterations` param, the walk's step limit (0: 10 × the target size)
    int targetVertices = 0; // the default of `target_vertices`, the size the cost steers toward (0: 20 × the example's)
    // Appendix A: the output is one connected piece — one starter, applied
    // once, and no rule that could split a piece (or remove the last one).
    bool connected = false;
    // Appendix B: edges drawn bent, each label by its brush's Bend (degrees).
    bool bend = false;
};

// The defaults the writer uses when WriterOptions leaves them 0.
int defaultTargetVertices(const LabelledExample& ex);
int defaultIterations(int targetVertices);


std::string writeGrammar(const LabelledExample& ex, const InferredGrammar& grammar, const WriterOptions& options);

}  // namespace g2d::infer
