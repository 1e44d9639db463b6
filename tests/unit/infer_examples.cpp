#include "infer_examples.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "infer/example_json.hpp"

namespace g2d::test {

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> merrellExamplePaths() {
    std::vector<std::string> out;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kMerrellExamples))
        if (entry.path().extension() == ".json") out.push_back(entry.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<std::pair<std::string, infer::LabelledExample>> merrellExamples() {
    std::vector<std::pair<std::string, infer::LabelledExample>> out;
    for (const std::string& path : merrellExamplePaths())
        out.emplace_back(path, infer::labelExample(infer::readExampleJson(readFile(path), path)));
    return out;
}

infer::LabelledExample merrellExample(const std::string& relative) {
    const std::string path = kMerrellExamples + "/" + relative;
    return infer::labelExample(infer::readExampleJson(readFile(path), path));
}

infer::InferOptions smallHierarchy() {
    infer::InferOptions o;
    o.maxGraphs = 600;
    return o;
}

}  // namespace g2d::test
