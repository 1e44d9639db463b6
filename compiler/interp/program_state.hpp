#pragma once
// What a run computes once, before the first step (lower::StartProgram):
// parameter values, constants, the kinds' attribute defaults, and the axiom
// graph.
#include <vector>

#include "g2d/graph.hpp"
#include "interp/evaluator.hpp"

namespace g2d::interp {

struct ProgramState {
    const ir::Program* prog = nullptr;
    std::vector<rt::Value> params, consts;
    std::vector<std::vector<rt::Value>> kindDefaults;   // per kind, per attribute

    EvalFrame frame(rt::Rng* rng) const;
};

std::vector<rt::KindInfo> kindInfos(const ir::Program& prog);
// Runs the program's start: fills `st` and returns the axiom graph. Throws EvalError.
rt::Graph startRun(const ir::Program& prog, std::vector<rt::Value> params, rt::Rng& rng, ProgramState& st);

}  // namespace g2d::interp
