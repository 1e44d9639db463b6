#pragma once
// `layout angles` in generated code: the same data the interpreter takes
// from the lowering (lower/angle_layout.hpp), printed as C++.
#include <optional>
#include <string>
#include <vector>

#include "g2d/angle_step.hpp"

namespace g2d::emit {

// The RuleSet::angleLayout() override (empty without `layout angles`).
std::string angleLayoutOverride(const std::optional<rt::AngleLayoutSpec>& spec);

}  // namespace g2d::emit
