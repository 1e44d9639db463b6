#pragma once
// G^3's command lists (Laganeckiene 2012, §2.4.6 and §3.3), as a grammar's
// `sequence { … }` and its compound commands give them: what the
// derivation runs, entry by entry, instead of the priorities.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace g2d::rt {

// An entry of a list: a rule (RuleSet's numbering), a compound command
// (RuleSet::compounds()), or a `repeat`: the `body` entries after it (nested
// repeats counted in) run as often as the run's count number `index` says
// (DerivationOptions::repeatCounts).
struct SequenceEntry {
    enum Kind { Rule, Compound, Repeat };
    Kind kind = Rule;
    std::size_t index = 0;
    std::size_t body = 0;
};

// A repeat's count as the run computed it: itself, or an OpError when it
// is negative (the back ends locate it at the count).
long long checkedRepeatCount(long long count);

// Calls `run` for each rule or compound entry of `list` in the order the
// list runs them, repeats unrolled with `counts`; stops when `run` returns
// false, and returns false then.
bool forEachCommand(const std::vector<SequenceEntry>& list, const std::vector<long long>& counts,
                    const std::function<bool(const SequenceEntry&)>& run);

// A compound command: its initial primitives are the matches of `matchRule`
// (a rule never applied); each one's scope runs `entries` (compound_run.hpp).
struct CompoundInfo {
    std::string name;
    std::size_t matchRule = 0;
    std::vector<SequenceEntry> entries;
};

}  // namespace g2d::rt
