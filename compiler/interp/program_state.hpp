#pragma once
// What a run computes once, before the first step (lower::StartProgram):
// parameter values, constants, the kinds' attribute defaults, and the axiom
// graph; and the lowered program the run executes.
#include <memory>
#include <vector>

#include "g2d/graph.hpp"
#include "interp/evaluator.hpp"
#include "lower/lowered_program.hpp"

namespace g2d::interp {

struct ProgramState {
    std::shared_ptr<const lower::LoweredProgram> lowered;   // made once for all the runs of a program
    std::vector<rt::Value> params, consts;
    std::vector<std::vector<rt::Value>> kindDefaults;   // per kind, per attribute

    // The program the lowered one is of (which owns what its operations point at).
    const ir::Program& program() const { return *lowered->ir; }
    EvalFrame frame(rt::Rng* rng) const;
};

std::vector<rt::KindInfo> kindInfos(const ir::Program& prog);
// Runs the program's start: fills `st` and returns the axiom graph. Throws EvalError.
rt::Graph startRun(std::shared_ptr<const lower::LoweredProgram> lowered, std::vector<rt::Value> params, rt::Rng& rng,
                   ProgramState& st);
// The same for a program run once (tests): lowers it first.
rt::Graph startRun(const ir::Program& prog, std::vector<rt::Value> params, rt::Rng& rng, ProgramState& st);

}  // namespace g2d::interp
