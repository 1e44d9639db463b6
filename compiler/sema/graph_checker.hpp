#pragma once
// Checks the axiom and the rules: their graphs, conditions, lets and daughters.
#include "sema/context.hpp"
#include "sema/expr_checker.hpp"

namespace g2d::sema {

void checkAxiom(Globals& g, ExprChecker& ec, const ast::AxiomDecl& d);
void checkRule(Globals& g, ExprChecker& ec, const ast::RuleDecl& d);

}  // namespace g2d::sema
