#include "interp/run_program.hpp"

namespace g2d::interp {

std::vector<rt::Value> defaultParams(const ir::Program& prog) {
    std::vector<rt::Value> out;
    for (const auto& p : prog.params) out.push_back(fromLiteral(p.defaultValue));
    return out;
}

RunResult runProgram(const ir::Program& prog, std::vector<rt::Value> params, std::uint64_t seed,
                     const rt::RunSettings& settings, const rt::StepObserver& observer, RunFailure* failure) {
    RunResult out;
    out.grammar = std::make_unique<InterpretedRun>(prog, nullptr);
    rt::RunProgress progress;
    try {
        rt::DerivedRun derived;
        rt::deriveGrammar(*out.grammar, params, seed, settings, derived, observer, &progress);
        out.derivation = derived.result;
        out.hitDefaultLimit = derived.hitDefaultLimit;
    } catch (const EvalError&) {
        if (failure) {
            failure->rule = out.grammar->currentRule();
            failure->step = progress.step + 1;
        }
        throw;
    }
    return out;
}

}  // namespace g2d::interp
