#pragma once
// `g2d infer EXAMPLE`: a graph grammar from an example shape (Merrell 2023).
#include <string>

#include "infer/grammar_inference.hpp"

namespace g2d {

struct InferCommandOptions {
    std::string example;          // the author's JSON format
    bool stats = false;           // print the numbers as one JSON object instead of the grammar
    infer::LabelOptions labels;
    infer::InferOptions limits;
};

int runInfer(const InferCommandOptions& options);

}  // namespace g2d
