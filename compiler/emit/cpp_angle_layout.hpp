#pragma once
// `layout angles` in generated code: the same data the interpreter takes
// from the lowering (lower/angle_layout.hpp), printed as C++.
#include <string>
#include <vector>

#include "g2d/angle_step.hpp"
#include "ir/ir.hpp"

namespace g2d::emit {

// `info.shapes = …;` for one rule (empty without `layout angles`).
std::string daughterShapesText(const std::vector<rt::DaughterShape>& shapes, const std::string& in);
// The RuleSet::angleLayout() override (empty without `layout angles`).
std::string angleLayoutOverride(const ir::Program& prog);

}  // namespace g2d::emit
