// Runs one fuzz check on saved inputs (files, or the files with the check's
// extensions anywhere under folders): the regression test for every input a
// fuzzer ever found, in the normal suite and under its sanitizers, without
// libFuzzer.
// Usage: fuzz_replay CHECK PATH...   (CHECK: a target of scripts/fuzz.sh;
// "g2d" runs front_end and interpreter, which read the same inputs)
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_checks.hpp"
#include "reader_checks.hpp"

namespace fs = std::filesystem;

namespace {

using Check = void (*)(const std::uint8_t*, std::size_t);

void checkGrammar(const std::uint8_t* data, std::size_t size) {
    g2d::fuzz::checkFrontEnd(data, size);
    g2d::fuzz::checkInterpreter(data, size);
}

struct NamedCheck {
    const char* name;
    Check check;
    std::vector<std::string> extensions;   // of the files taken from a folder ("" for none)
};

const std::vector<NamedCheck>& checks() {
    using namespace g2d::fuzz;
    static const std::vector<NamedCheck> all = {
        {"g2d", checkGrammar, {".g2d", ""}},
        {"infer_json", checkInferJson, {".json"}},
        {"infer_svg", checkInferSvg, {".svg"}},
        {"svg_attribute", checkSvgAttribute, {".txt"}},
        {"import_yaml", checkImportYaml, {".yml", ".yaml"}},
        {"python_expression", checkPythonExpression, {".py"}},
        {"lsp", checkLanguageServer, {".g2d", ".lsp"}},
        {"inference", checkInferenceOnDrawing, {".bin"}},
    };
    return all;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: fuzz_replay CHECK PATH...\n");
        return 2;
    }
    const auto& all = checks();
    const auto it = std::find_if(all.begin(), all.end(), [&](const NamedCheck& c) { return std::strcmp(c.name, argv[1]) == 0; });
    if (it == all.end()) {
        std::fprintf(stderr, "fuzz_replay: no check %s\n", argv[1]);
        return 2;
    }
    auto wanted = [&](const fs::path& p) {
        return std::find(it->extensions.begin(), it->extensions.end(), p.extension().string()) != it->extensions.end();
    };
    std::vector<fs::path> inputs;
    for (int i = 2; i < argc; ++i) {
        const fs::path p = argv[i];
        if (!fs::exists(p)) continue;   // a check no fuzzer has found anything with yet
        if (fs::is_directory(p)) {
            for (const auto& entry : fs::recursive_directory_iterator(p))
                if (entry.is_regular_file() && wanted(entry.path())) inputs.push_back(entry.path());
        } else {
            inputs.push_back(p);
        }
    }
    std::sort(inputs.begin(), inputs.end());
    for (const auto& p : inputs) {
        std::ifstream in(p, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        it->check(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    }
    std::printf("%zu inputs checked by %s\n", inputs.size(), it->name);
    return inputs.empty() ? 1 : 0;
}
