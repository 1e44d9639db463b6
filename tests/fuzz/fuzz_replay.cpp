// Runs the fuzz checks on saved inputs (files, or every file in folders):
// the regression test for every input a fuzzer ever found, in the normal
// suite and under its sanitizers, without libFuzzer.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_checks.hpp"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    std::vector<fs::path> inputs;
    for (int i = 1; i < argc; ++i) {
        const fs::path p = argv[i];
        if (fs::is_directory(p)) {
            for (const auto& entry : fs::directory_iterator(p))
                if (entry.is_regular_file()) inputs.push_back(entry.path());
        } else {
            inputs.push_back(p);
        }
    }
    std::sort(inputs.begin(), inputs.end());
    for (const auto& p : inputs) {
        std::ifstream in(p, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
        g2d::fuzz::checkFrontEnd(data, bytes.size());
        g2d::fuzz::checkInterpreter(data, bytes.size());
    }
    std::printf("%zu inputs checked\n", inputs.size());
    return inputs.empty() ? 1 : 0;
}
