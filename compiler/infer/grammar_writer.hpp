#pragma once
// An inferred grammar written as `.g2d` source (docs/infer.md, "Generation"):
// one node kind per primitive, one directed edge kind per edge label with its
// direction, lengths and areas for the `layout angles` drawing step, one face
// kind per area, and each rule L <-> R as two `dpo` rules (a starter as
// Start/Stop from and to nothing). Running it is Merrell's Algorithm 3.
#include <string>

#include "infer/grammar_inference.hpp"

namespace g2d::infer {

struct WriterOptions {
    std::string source;     // the example's path, for the header comment
    int iterations = 1000;  // the default of the `iterations` param: the walk's step limit
};

std::string writeGrammar(const LabelledExample& ex, const InferredGrammar& grammar, const WriterOptions& options);

}  // namespace g2d::infer
