#include "interp/run_program.hpp"

#include "interp/interpreted_rules.hpp"

namespace g2d::interp {

std::vector<rt::Value> defaultParams(const ir::Program& prog) {
    std::vector<rt::Value> out;
    for (const auto& p : prog.params) out.push_back(fromLiteral(p.defaultValue));
    return out;
}

RunResult runProgram(const ir::Program& prog, std::vector<rt::Value> params, std::uint64_t seed,
                     std::optional<long long> steps, const rt::StepObserver& observer, RunFailure* failure) {
    rt::Rng rng(seed);
    RunResult out;
    out.state = initState(prog, std::move(params), rng);
    out.graph = buildAxiom(out.state, rng);
    InterpretedRules rules(out.state);

    rt::DerivationLimits limits;
    EvalFrame frame = out.state.frame(nullptr);
    if (steps) limits.steps = *steps;
    else if (prog.stepLimit) limits.steps = std::get<long long>(evaluate(*prog.stepLimit, frame));
    else limits.steps = kDefaultStepLimit;
    for (const auto& [prio, cfg] : prog.priorities)
        if (cfg.limit) limits.perPriority[prio] = std::get<long long>(evaluate(*cfg.limit, frame));

    long long step = 0;
    try {
        out.derivation = rt::derive(out.graph, rules, rng, limits, [&](long long s, const rt::Graph& g) {
            step = s;
            if (observer) observer(s, g);
        });
    } catch (const EvalError&) {
        if (failure) {
            failure->rule = rules.currentRule() ? rules.currentRule()->name : "";
            failure->step = step + 1;
        }
        throw;
    }
    out.hitDefaultLimit = out.derivation.stopped == rt::StopReason::StepLimit && !steps && !prog.stepLimit;
    return out;
}

}  // namespace g2d::interp
