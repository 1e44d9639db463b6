#pragma once
// What a rule's matches read, by kind and by attribute (rt::RuleInfo::
// readKinds, readValues; what its daughters change is read off their
// rewrites: rewrite_effects.hpp): after a step whose daughter changes no kind another rule
// reads, that rule's matches are as they were, so the runtime does not
// repair its set (a strip's rewrite leaves the rules about squares alone); a
// node whose only change is an attribute a rule does not read leaves the
// rule's matches binding it alone (a centre counting its leaves).
#include <vector>

#include "ir/ir.hpp"
#include "lower/kind_set.hpp"

namespace g2d::lower {

struct KindEffects {
    // The kinds (node and edge kinds share Program::kinds' numbering) whose
    // elements a change of can change the rule's matches: those of its
    // pattern and its negative conditions (a wildcard node: every node kind;
    // an edge without a kind: every edge kind), and every edge kind where a
    // condition reads a degree (readsDegrees). Sorted.
    std::vector<int> readKinds;
    bool readsDegrees = false;
    bool readsNeighbours = false;                   // a condition reads a face's `neighbours`
    // The node attributes its conditions (and its negative conditions')
    // read, as valueKey. Sorted.
    std::vector<long long> readValues;
};

KindEffects kindEffects(const ir::Rule& rule, const std::vector<ir::Kind>& kinds);

}  // namespace g2d::lower
