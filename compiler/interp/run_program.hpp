#pragma once
// One whole interpreted run, without outputs: for tests and tools. `g2d run`
// goes through the runtime's driver (g2d/run_driver.hpp) with the same
// InterpretedRun.
#include <memory>
#include <optional>
#include <string>

#include "g2d/derive_grammar.hpp"
#include "interp/interpreted_run.hpp"

namespace g2d::interp {

using rt::kDefaultStepLimit;

struct RunResult {
    std::unique_ptr<InterpretedRun> grammar;
    rt::DerivationResult derivation;
    bool hitDefaultLimit = false;   // stopped by the 10 000-step default (the grammar sets no limit)

    const rt::Graph& graph() const { return grammar->graph(); }
    const ProgramState& state() const { return grammar->state(); }
};

struct RunFailure {
    std::string rule;               // the rule being applied ("" before the first step)
    long long step = 0;
};

// Throws EvalError (with `failure` filled in) and rt::RunawayError.
RunResult runProgram(const ir::Program& prog, std::vector<rt::Value> params, std::uint64_t seed,
                     const rt::RunSettings& settings, const rt::StepObserver& observer = {},
                     RunFailure* failure = nullptr);

std::vector<rt::Value> defaultParams(const ir::Program& prog);

}  // namespace g2d::interp
