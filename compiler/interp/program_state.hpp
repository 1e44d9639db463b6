#pragma once
// What a run computes once, before the first step: parameter values,
// constants (in declaration order, drawing from the generator), the kinds'
// attribute defaults, and the axiom graph.
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

// Throws EvalError.
ProgramState initState(const ir::Program& prog, std::vector<rt::Value> params, rt::Rng& rng);
std::vector<rt::KindInfo> kindInfos(const ir::Program& prog);
// Builds the axiom: nodes in order (position, then attributes), then edges.
rt::Graph buildAxiom(const ProgramState& st, rt::Rng& rng);

}  // namespace g2d::interp
