#pragma once
// The `dpo` rule option's dangling condition (double pushout: an
// application that would leave an edge without an end is not made),
// written as ordinary match conditions so that matching, incremental repair
// and both back ends treat it like any `where`.
#include "ir/ir.hpp"

namespace g2d::sema {

// For every match node some daughter deletes: `x.degree == k`, k the
// pattern's edges at x (a loop counts once, as `degree` counts it).
void addDanglingConditions(ir::Rule& rule);

}  // namespace g2d::sema
