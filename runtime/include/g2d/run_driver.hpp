#pragma once
// The run procedure shared by `g2d run` and compiled grammars:
// RUN [-o OUT.svg] [--json OUT.json] [--no-svg] [--seed N] [-D NAME=VALUE]…
//     [--steps N] [--stats]
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "g2d/grammar_run.hpp"

namespace g2d::rt {

inline constexpr long long kDefaultStepLimit = 10000;

struct RunRequest {
    std::string grammarFile;              // the .g2d file (messages, default output name)
    std::optional<std::string> svgOut;    // default: the grammar's name with .svg, in the current folder
    std::optional<std::string> jsonOut;
    bool noSvg = false;
    std::uint64_t seed = 1;
    std::vector<std::string> defines;     // NAME=VALUE
    std::optional<long long> steps;       // overrides the grammar's global limit
    bool stats = false;
    std::optional<long long> maxElements; // the runaway guard (default kDefaultMaxElements)
};

struct DerivedRun {
    DerivationResult result;
    bool hitDefaultLimit = false;    // stopped by kDefaultStepLimit: the grammar sets no limit
};

// Starts the grammar with `params` and derives it with a generator seeded by
// `seed`. `lastStep` follows the step being done (for error messages).
DerivedRun deriveGrammar(GrammarRun& grammar, const std::vector<Value>& params, std::uint64_t seed,
                         std::optional<long long> steps, const StepObserver& observer = {},
                         long long* lastStep = nullptr, std::size_t maxElements = kDefaultMaxElements);

// Runs and writes the outputs. Returns the exit code: 0 done, 1 a run-time
// error or an unwritable output, 2 bad arguments. Messages go to stderr,
// `--stats` to stdout.
int runGrammar(const RunRequest& request, GrammarRun& grammar);

// For compiled programs: reads the command line into a request. Returns an
// exit code (0 after --help, 2 on a usage error) when the program should stop.
std::optional<int> parseRunArguments(int argc, char** argv, const std::string& grammarFile, RunRequest& out);

// `FILE:LINE:COL: error: MESSAGE`, the source line and a caret.
std::string renderLocatedError(const SourceLocation& at, const std::string& message);

}  // namespace g2d::rt
