#pragma once
// What the runtime's scheduler and incremental matching know of a rule
// (rt::RuleInfo), decided once from the IR for both back ends: the
// interpreter uses it as it is, the emitter prints it as data. A weight
// given by an expression of parameters is the one thing left to the run.
#include <vector>

#include "g2d/derivation.hpp"
#include "ir/ir.hpp"
#include "lower/rewrite_program.hpp"

namespace g2d::lower {

struct RuleFacts {
    rt::RuleInfo info;                          // weights: the known ones, 0 where weightExprs has one
    std::vector<const ir::Expr*> weightExprs;   // per daughter: the weight's expression of parameters, or null
    std::vector<const ir::Expr*> matchWeightExprs;   // per daughter: the weight's expression reading the match, or null
    const ir::Expr* choiceWeightExpr = nullptr; // the rule's `weight` when it reads parameters (info's is 0 then)
    const ir::Expr* mergeExpr = nullptr;        // the merge tolerance when it reads parameters (info's is 0 then)
};

// `daughters`: the rule's lowered rewrites (what they change is theirs).
RuleFacts ruleFacts(const ir::Program& prog, const ir::Rule& rule, const std::vector<RewriteProgram>& daughters);
// The same, lowering the rewrites itself (tests).
RuleFacts ruleFacts(const ir::Program& prog, const ir::Rule& rule);

}  // namespace g2d::lower
