// g2d infer at the paper's scale (issue #44): with the defaults, the written
// grammar's outputs are many times the example's size (median over the
// author's 45 examples at least 10x), every vertex's star is one of the
// example's primitives, and the output differs from the example; with
// --connected every output is one piece. Under the sanitizers every fifth
// example only.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "infer/grammar_writer.hpp"
#include "infer_examples.hpp"
#include "inferred_output.hpp"
#include "interp/run_program.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

constexpr int kEvery = G2D_SANITIZED ? 5 : 1;

struct Output {
    int vertices = 0, pieces = 0;
    bool similar = true;
};

// The output of `ex`'s grammar (seed 1, the written defaults) and its local similarity.
Output generate(const infer::LabelledExample& ex, const infer::InferredGrammar& grammar, bool connected) {
    infer::WriterOptions writer;
    writer.connected = connected;
    const CompileResult compiled = test::compile(infer::writeGrammar(ex, grammar, writer), "inferred.g2d");
    INFO(test::firstError(compiled));
    REQUIRE(compiled.program);
    const ir::Program& prog = *compiled.program;
    const interp::RunResult run = interp::runProgram(prog, interp::defaultParams(prog), 1, rt::RunSettings{});
    const fuzz::InferredOutput measured = fuzz::measureInferredOutput(ex, prog, run.graph());
    return {measured.vertices, measured.pieces, measured.dissimilar < 0};
}

}  // namespace

TEST_CASE("inferred grammars' outputs are ten times the example or more, locally similar, and --connected ones one piece",
          "[infer][generation][large]") {
    std::vector<double> ratios;
    int connectedLarge = 0, examples = 0;
    const auto all = test::merrellExamples();
    for (std::size_t i = 0; i < all.size(); i += kEvery) {
        const auto& [path, ex] = all[i];
        INFO(path);
        const infer::InferredGrammar grammar = infer::inferGrammar(ex, infer::InferOptions{});
        const Output free = generate(ex, grammar, false);
        const Output joined = generate(ex, grammar, true);
        const double size = static_cast<double>(ex.shape.vertices.size());
        ratios.push_back(free.vertices / size);
        CHECK(free.similar);
        CHECK(joined.similar);
        CHECK(free.vertices != static_cast<int>(size));   // not the example again
        CHECK(joined.pieces == 1);
        connectedLarge += joined.vertices >= 5 * size ? 1 : 0;
        ++examples;
    }
    std::sort(ratios.begin(), ratios.end());
    const double median = ratios[ratios.size() / 2];
    INFO("median output / example: " << median << "; --connected outputs of 5x the example or more: " << connectedLarge << " of "
                                     << examples);
    CHECK(median >= 10);
    // Not yet the target (most examples' connected outputs stay near the
    // example's size: docs/infer.md); a guard against losing what is reached.
    // Six of the 45 (and under the sanitizers, of every 5th: 9, the share rounded down).
    CHECK(connectedLarge >= 6 * examples / 45);
}
