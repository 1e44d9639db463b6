#pragma once
// Checks `canvas LOWER to UPPER;`, the SVG's fixed viewBox (g2d/view_box.hpp,
// docs/language.md §6): two vec2 corners, constant or from parameters; when
// known now, a box that is not empty.
#include "sema/context.hpp"
#include "sema/expr_checker.hpp"

namespace g2d::sema {

void checkCanvas(Globals& g, ExprChecker& ec, const ast::CanvasDecl& d);

}  // namespace g2d::sema
