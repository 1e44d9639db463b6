#pragma once
// What a rule's matches read and what its daughters change, by kind and by
// node attribute (ir::Rule::readKinds and readValues,
// ir::Daughter::changedKinds and changedValues): after a step whose
// daughter changes no kind another rule reads, that rule's matches are as
// they were, so the runtime does not repair its set (a strip's rewrite
// leaves the rules about squares alone); a node whose only change is an
// attribute a rule does not read leaves the rule's matches binding it
// alone (a centre counting its leaves).
#include "ir/ir.hpp"

namespace g2d::sema {

// Fills rule.readKinds, rule.readsDegrees, rule.readValues and every
// daughter's changedKinds and changedValues, for a rule whose match,
// negative conditions and daughters are built; `kinds` are the program's.
void describeKindEffects(ir::Rule& rule, const std::vector<ir::Kind>& kinds);

}  // namespace g2d::sema
