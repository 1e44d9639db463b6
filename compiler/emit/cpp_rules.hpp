#pragma once
// Emits one rule: its matcher (the search plan as nested loops), its negative
// conditions, and for each daughter the write set and the prepare/commit code.
#include <string>

#include "emit/cpp_expr.hpp"
#include "lower/lowered_program.hpp"

namespace g2d::emit {

// `firstDaughter` numbers the rule's first daughter among all rules' daughters
// (the key of its pending rewrites).
std::string emitRule(const ir::Program& prog, const lower::LoweredRule& rule, int ruleIndex, int firstDaughter, ExprGen& gen,
                     Places& places, ConstantValues& constants);

}  // namespace g2d::emit
