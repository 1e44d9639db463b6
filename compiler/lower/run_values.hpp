#pragma once
// The values a run computes outside the rewrites, as data both back ends
// read: a rule's numbers given by parameters (before the first step), the
// weights that read the match (per application), and a compound's lets (per
// instance). What is evaluated, which check applies and where a failure is
// placed are decided here, once.
#include <vector>

#include "g2d/ops.hpp"
#include "ir/ir.hpp"
#include "lower/rewrite_program.hpp"

namespace g2d::lower {

// A runtime check (g2d/ops.hpp) as the interpreter calls it and the
// generated code names it.
struct NumberCheck {
    double (*check)(double);
    const char* name;
};
inline constexpr NumberCheck kWeightCheck{rt::checkedWeight, "checkedWeight"};
inline constexpr NumberCheck kMergeToleranceCheck{rt::checkedMergeTolerance, "checkedMergeTolerance"};

// A number of the rule's RuleInfo that a parameter gives: `value`, checked,
// into `field` (a failure is placed at the value).
struct SetRuleNumber {
    enum class Field : std::uint8_t { DaughterWeight, ChoiceWeight, MergeTolerance };
    Field field;
    int daughter = -1;                   // DaughterWeight's
    const ir::Expr* value = nullptr;
    NumberCheck check;
};

// A match-weighted rule's weights, per application: each is checked by
// rt::checkedMatchWeight (a failure placed at its value), then all by
// rt::checkSomeWeight (placed at the first).
struct MatchWeights {
    struct Weight {
        int daughter;
        const ir::Expr* value;
    };
    std::vector<Weight> weights;
};

// A compound's lets, on a match of its match rule: into the rule's local
// slots, in order; the instance's values are the slots' in that order.
struct CompoundLets {
    int matchRule = -1;
    std::vector<EvalLocal> lets;
};

}  // namespace g2d::lower
