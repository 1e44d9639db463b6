#include "lower/lowered_program.hpp"

#include "lower/angle_layout.hpp"
#include "lower/command_lists.hpp"

namespace g2d::lower {

LoweredProgram lowerProgram(const ir::Program& prog) {
    LoweredProgram out;
    out.ir = &prog;
    out.start = lowerStart(prog);
    out.rules.reserve(prog.rules.size());
    for (const auto& r : prog.rules) {
        LoweredRule& rule = out.rules.emplace_back();
        rule.rule = &r;
        rule.match = lowerMatch(prog, r);
        for (std::size_t d = 0; d < r.daughters.size(); ++d) rule.daughters.push_back(lowerRewrite(prog, r, d));
        rule.facts = ruleFacts(prog, r, rule.daughters);
    }
    out.sequence = sequenceOf(prog);
    out.compounds = compoundsOf(prog);
    for (const auto& c : prog.compounds) {
        CompoundLets& lets = out.compoundLets.emplace_back();
        lets.matchRule = c.matchRule;
        for (const auto& l : prog.rules[static_cast<std::size_t>(c.matchRule)].lets) lets.lets.push_back(EvalLocal{l.slot, &l.value});
    }
    out.angleLayout = angleLayoutSpec(prog);
    return out;
}

}  // namespace g2d::lower
