#pragma once
// `layout angles` for the runtime (g2d/angle_step.hpp), decided once from
// the IR for both back ends: the interpreter uses it as it is, the emitter
// prints it as data.
#include <optional>

#include "g2d/angle_step.hpp"
#include "ir/ir.hpp"

namespace g2d::lower {

// Null without `layout angles`.
std::optional<rt::AngleLayoutSpec> angleLayoutSpec(const ir::Program& prog);

}  // namespace g2d::lower
