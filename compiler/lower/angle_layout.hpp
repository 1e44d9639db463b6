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

// What daughter `d` of `rule` does to the graph. A kept edge given new ends
// counts as removed and made again (its drawing is new).
rt::DaughterShape daughterShape(const ir::Rule& rule, std::size_t d);

}  // namespace g2d::lower
