#pragma once
// One derivation of a grammar as a back end provides it (GrammarRun), the
// same for every caller: the embedding API (grammar.hpp), `g2d run` and
// compiled programs (run_driver.hpp), and the tests. It starts the grammar,
// applies its limits and canvas, derives, then finishes a `layout angles`
// drawing (its faces and bent edges).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "g2d/derivation.hpp"
#include "g2d/grammar_run.hpp"

namespace g2d::rt {

// The step limit of a grammar that sets none: past it, a run reports that
// the grammar may not terminate.
inline constexpr long long kDefaultStepLimit = 10000;

// The bounds of one derivation.
struct RunSettings {
    std::optional<long long> steps;       // overrides the grammar's global limit
    std::size_t maxElements = kDefaultMaxElements;
    std::optional<double> timeoutSeconds;
    bool verifyMatches = false;
    bool wholeDrawings = false;           // DerivationOptions::wholeDrawings (tests)
};

// How far a derivation got (kept up to date while it runs, for errors).
struct RunProgress {
    bool started = false;                 // the axiom was built; the graph is a completed step
    long long step = 0;                   // the last completed step
};

struct DerivedRun {
    DerivationResult result;
    bool hitDefaultLimit = false;    // stopped by kDefaultStepLimit: the grammar sets no limit
    std::optional<ViewBox> canvas;   // the grammar's `canvas`, evaluated with the parameters
};

// Starts the grammar with `params` and derives it with a generator seeded by
// `seed`. `progress` follows the derivation (for error messages).
// With `tracer`, every step is followed (StepTracer::started once the axiom
// is built). `out` is kept up to date, so after an exception it describes
// the completed steps.
void deriveGrammar(GrammarRun& grammar, const std::vector<Value>& params, std::uint64_t seed, const RunSettings& settings,
                   DerivedRun& out, const StepObserver& observer = {}, RunProgress* progress = nullptr,
                   StepTracer* tracer = nullptr);

// `FILE:LINE:COL: error: MESSAGE`, the source line and a caret.
std::string renderLocatedError(const SourceLocation& at, const std::string& message);

}  // namespace g2d::rt
