#pragma once
// Checks Merrell 2023's drawing step as the language writes it: the
// grammar's `layout angles { … }` and edge kinds' `layout { … }` blocks
// (docs/language.md §9.4). Their values are constants, folded here, so both
// back ends read plain numbers.
#include "sema/context.hpp"
#include "sema/expr_checker.hpp"

namespace g2d::sema {

void checkLayoutDecl(Globals& g, ExprChecker& ec, const ast::LayoutDecl& d);
// An edge kind's `layout { angle = …; length = …; left = Face; right = Face; }`.
void checkEdgeLayout(Globals& g, ExprChecker& ec, const ast::KindDecl& d);
// With `layout angles`: every edge kind has a layout, and no rule places or
// merges nodes itself or rewrites several matches at once (the drawing step
// decides each application). Run after the rules are checked.
void checkAngleLayoutUse(Globals& g, const std::vector<const ast::KindDecl*>& kinds);

}  // namespace g2d::sema
