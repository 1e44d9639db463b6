#pragma once
// What the runtime's scheduler and incremental matching know of a rule
// (rt::RuleInfo), decided once from the IR for both back ends: the
// interpreter uses it as it is, the emitter prints it as data. The numbers
// parameters give are left to the run, as SetRuleNumber.
#include <vector>

#include "g2d/derivation.hpp"
#include "ir/ir.hpp"
#include "lower/rewrite_program.hpp"
#include "lower/run_values.hpp"

namespace g2d::lower {

struct RuleFacts {
    rt::RuleInfo info;                          // the numbers startNumbers sets are 0
    std::vector<SetRuleNumber> startNumbers;    // what parameters give, in order
    MatchWeights matchWeights;                  // the weights reading the match (info.matchWeighted)
};

// `daughters`: the rule's lowered rewrites (what they change is theirs).
RuleFacts ruleFacts(const ir::Program& prog, const ir::Rule& rule, const std::vector<RewriteProgram>& daughters);
// The same, lowering the rewrites itself (tests).
RuleFacts ruleFacts(const ir::Program& prog, const ir::Rule& rule);

}  // namespace g2d::lower
