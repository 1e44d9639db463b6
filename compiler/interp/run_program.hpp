#pragma once
// One whole interpreted run: state, axiom, derivation. Used by `g2d run` and
// by the tests, so both exercise the same path.
#include <optional>
#include <string>

#include "g2d/derivation.hpp"
#include "interp/program_state.hpp"

namespace g2d::interp {

inline constexpr long long kDefaultStepLimit = 10000;

struct RunResult {
    ProgramState state;
    rt::Graph graph{{}};
    rt::DerivationResult derivation;
    bool hitDefaultLimit = false;   // stopped by the 10 000-step default (the grammar sets no limit)
};

struct RunFailure {
    std::string rule;               // the rule being applied ("" before the first step)
    long long step = 0;
};

// Throws EvalError (with `failure` filled in) and rt::RunawayError.
RunResult runProgram(const ir::Program& prog, std::vector<rt::Value> params, std::uint64_t seed,
                     std::optional<long long> steps, const rt::StepObserver& observer = {},
                     RunFailure* failure = nullptr);

std::vector<rt::Value> defaultParams(const ir::Program& prog);

}  // namespace g2d::interp
