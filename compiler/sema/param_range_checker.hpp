#pragma once
// Checks a parameter's `in MIN..MAX [step STEP]` (docs/language.md §5.2):
// int and float parameters only, constant bounds with MIN <= MAX, the default
// within them, a step above 0. Fills the parameter's min, max and step.
#include "sema/context.hpp"
#include "sema/expr_checker.hpp"

namespace g2d::sema {

// `defaultKnown`: p.defaultValue holds the folded default (no error in it).
void checkParamRange(Globals& g, ExprChecker& ec, const ast::ParamDecl& d, ir::Param& p, bool defaultKnown);

}  // namespace g2d::sema
