#include "driver/infer_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "infer/example_json.hpp"
#include "infer/example_svg.hpp"
#include "g2d/atomic_file.hpp"
#include "infer/grammar_report.hpp"
#include "infer/grammar_writer.hpp"

namespace g2d {

int runInfer(const InferCommandOptions& options) {
    if (options.sizeGiven && options.size < 1) {
        std::fprintf(stderr, "g2d infer: error: --size %d: the target number of vertices must be at least 1\n", options.size);
        return 1;
    }
    if (options.unitGiven && !(options.labels.lengthUnit > 0 && std::isfinite(options.labels.lengthUnit))) {
        std::fprintf(stderr, "g2d infer: error: --length-unit %g: lengths are whole multiples of it, so it must be positive\n",
                     options.labels.lengthUnit);
        return 1;
    }
    std::ifstream in(options.example, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "g2d infer: error: cannot read %s\n", options.example.c_str());
        return 1;
    }
    std::stringstream text;
    text << in.rdbuf();
    try {
        const auto start = std::chrono::steady_clock::now();
        const bool svg = options.example.size() >= 4 && options.example.compare(options.example.size() - 4, 4, ".svg") == 0;
        const infer::LabelledExample ex = infer::labelExample(
            svg ? infer::readExampleSvg(text.str(), options.example) : infer::readExampleJson(text.str(), options.example), options.labels);
        const infer::InferredGrammar grammar = infer::inferGrammar(ex, options.limits);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const std::string out = options.stats ? infer::inferenceStatsJson(infer::countInference(ex, grammar), ms)
                                              : infer::describeGrammar(ex, grammar);
        if (!options.output.empty()) {
            infer::WriterOptions writer;
            writer.source = options.example;
            writer.iterations = options.iterations;
            writer.targetVertices = options.size;
            writer.connected = options.connected;
            writer.bend = options.bend;
            rt::AtomicFile file(options.output);
            file.commit(infer::writeGrammar(ex, grammar, writer));
        }
        std::fwrite(out.data(), 1, out.size(), stdout);
    } catch (const rt::OutputError& e) {
        std::fprintf(stderr, "g2d infer: error: %s\n", e.what());
        return 1;
    } catch (const infer::InputError& e) {
        std::fprintf(stderr, "g2d infer: error: %s\n", e.message.c_str());
        return 1;
    }
    return 0;
}

}  // namespace g2d
