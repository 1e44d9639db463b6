#pragma once
// What a rule's matches read and what its daughters change, by kind
// (ir::Rule::readKinds, ir::Daughter::changedKinds): after a step whose
// daughter changes no kind another rule reads, that rule's matches are as
// they were, so the runtime does not repair its set (a strip's rewrite
// leaves the rules about squares alone).
#include "ir/ir.hpp"

namespace g2d::sema {

// Fills rule.readKinds, rule.readsDegrees and every daughter's
// changedKinds, for a rule whose match, negative conditions and daughters
// are built; `kinds` are the program's.
void describeKindEffects(ir::Rule& rule, const std::vector<ir::Kind>& kinds);

}  // namespace g2d::sema
