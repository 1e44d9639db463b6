#pragma once
// Warnings about a well-typed program: rules that can never match, unused names.
#include "sema/context.hpp"

namespace g2d::sema {

void lintProgram(Globals& g);

}  // namespace g2d::sema
