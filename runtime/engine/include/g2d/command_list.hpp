#pragma once
// G^3's command lists (Laganeckiene 2012, §2.4.6 and §3.3), as a grammar's
// `sequence { … }` and its compound commands give them: what the
// derivation runs, entry by entry, instead of the priorities.
#include <cstddef>
#include <string>
#include <vector>

namespace g2d::rt {

// An entry of a list: a rule (RuleSet's numbering), or a compound command
// (RuleSet::compounds()).
struct SequenceEntry {
    bool compound = false;
    std::size_t index = 0;
};

// A compound command: its initial primitives are the matches of `matchRule`
// (a rule never applied); each one's scope runs `entries` (compound_run.hpp).
struct CompoundInfo {
    std::string name;
    std::size_t matchRule = 0;
    std::vector<SequenceEntry> entries;
};

}  // namespace g2d::rt
