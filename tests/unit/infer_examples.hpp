#pragma once
// The author's 45 examples (examples/infer/merrell), read and labelled, for
// the g2d infer tests.
#include <string>
#include <utility>
#include <vector>

#include "infer/grammar_inference.hpp"

namespace g2d::test {

inline const std::string kMerrellExamples = G2D_SOURCE_DIR "/examples/infer/merrell";

std::string readFile(const std::string& path);
// Every example's path, sorted.
std::vector<std::string> merrellExamplePaths();
// Every example, labelled, by path (sorted).
std::vector<std::pair<std::string, infer::LabelledExample>> merrellExamples();
// One example by its path under the folder ("2D Basic Shapes/L.json").
infer::LabelledExample merrellExample(const std::string& relative);
// A hierarchy small enough for tests over every example.
infer::InferOptions smallHierarchy();

}  // namespace g2d::test
