#pragma once
// `g2d infer EXAMPLE`: a graph grammar from an example shape (Merrell 2023).
#include <string>

#include "infer/grammar_inference.hpp"

namespace g2d {

struct InferCommandOptions {
    std::string example;          // the author's JSON format
    bool stats = false;           // print the numbers as one JSON object instead of the grammar
    std::string output;           // -o: write the grammar as .g2d here (whole or not at all)
    int iterations = 0;           // the written grammar's default step limit (Algorithm 3's N; 0: from the size)
    int size = 0;                 // --size: the written grammar's target number of vertices (0: 20 × the example's)
    bool sizeGiven = false;
    bool unitGiven = false;       // --length-unit
    bool connected = false;       // --connected (Appendix A)
    bool bend = false;            // --bend (Appendix B)
    infer::LabelOptions labels;
    infer::InferOptions limits;
};

int runInfer(const InferCommandOptions& options);

}  // namespace g2d
