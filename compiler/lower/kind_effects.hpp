#pragma once
// What a rule's matches read and what its daughters change, by kind and by
// node attribute (rt::RuleInfo::readKinds, readValues, changedKinds,
// changedValues): after a step whose daughter changes no kind another rule
// reads, that rule's matches are as they were, so the runtime does not
// repair its set (a strip's rewrite leaves the rules about squares alone); a
// node whose only change is an attribute a rule does not read leaves the
// rule's matches binding it alone (a centre counting its leaves).
#include <vector>

#include "ir/ir.hpp"

namespace g2d::lower {

// A node attribute as one number (KindEffects::readValues, changedValues).
inline long long valueKey(int kind, int attribute) { return static_cast<long long>(kind) << 32 | static_cast<unsigned>(attribute); }

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
    // Per daughter: the kinds of the elements applying it removes, adds or
    // changes (a position, the kind, an edge's ends or attributes; not a
    // style, which no condition reads), and the attributes it writes on kept
    // nodes (those alone leave a node's kind out of changedKinds). Sorted.
    // Removing a node also removes its edges, of any kind: a rule reading
    // degrees sees that through the daughter's deleted nodes.
    std::vector<std::vector<int>> changedKinds;
    std::vector<std::vector<long long>> changedValues;
};

KindEffects kindEffects(const ir::Rule& rule, const std::vector<ir::Kind>& kinds);

}  // namespace g2d::lower
