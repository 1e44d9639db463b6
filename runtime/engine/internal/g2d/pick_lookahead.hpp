#pragma once
// Prefetching for the picks of the coming steps.
//
// With millions of matches, a random pick lands on records no recent step
// touched: the match's slot in the set, its record, its nodes and edges,
// their lists in the sets. Each is a cache miss, and the step waits for them
// in turn: at Koch level 10 they took two thirds of a step. But the pick a
// later step makes is known ahead when nothing else draws random numbers in
// between: the generator's next outputs are fixed, and the set's size
// changes by one of a few amounts a step (random picks: the guesses take
// the last two distinct growths); oldest picks come from the lowest age
// groups in turn. So each step, for the picks one to four steps ahead, this
// asks for the set's slot (four ahead), the match's record (three ahead: its
// slot is cached by now), the match's elements (two ahead: its record is
// cached by now) and the data its rewrite reads beyond them (one ahead, from
// the rule set: a compiled grammar's attribute records, whose places the
// elements' records hold), while the current step runs.
//
// Only a copy of the generator is advanced, so a wrong guess (another rule
// applies, a daughter draws numbers, the size changes otherwise) costs a
// few prefetches, never a different result.
#include <cstddef>
#include <cstdint>

#include "g2d/derivation.hpp"
#include "g2d/incremental_matches.hpp"

namespace g2d::rt {

class PickLookahead {
public:
    // Called with each step's pick, as soon as it is drawn: whether the
    // last step guessed it (its records are then on their way already).
    bool guessed(Match picked);
    // Called once a step has drawn `picked` (and its daughter) from `rule`'s
    // `set`, before the step is applied; `rng` is the generator then.
    void ahead(std::size_t rule, const RuleInfo& info, const MatchSet& set, Match picked, const Rng& rng,
               const IncrementalMatches& sets, const RuleSet& rules, const Graph& g);
    // How often a step's pick had been guessed one step ahead, and how
    // often a guess was the record then drawn (for --stats and tests).
    long long guesses() const { return guesses_; }
    long long hits() const { return hits_; }

    // Below this many matches a set's records (and their elements, about
    // 200 bytes a match) stay in the processor's caches or come quickly
    // enough: guessing costs more than it saves (measured: Koch oldest level
    // 7, up to 49,152 matches, 4 % slower from 8,192 on; level 8 3 % faster).
    static constexpr std::size_t kMinMatches = 32768;

private:
    static constexpr int kAhead = 4;   // steps
    void aheadOldest(std::size_t rule, const RuleInfo& info, const MatchSet& set, Match picked, const Rng& rng,
                     const IncrementalMatches& sets, const RuleSet& rules, const Graph& g);
    static constexpr std::size_t kNone = ~std::size_t{0};
    std::size_t rule_ = kNone;      // the rule the last step picked from
    std::size_t lastSize_ = 0;      // its set's size then
    long long growth_[2] = {0, 0};  // the last two distinct growths of its set per step, latest first
    const std::uint32_t* guessed_[2] = {nullptr, nullptr};   // the records guessed for the next pick
    long long guesses_ = 0, hits_ = 0;
};

}  // namespace g2d::rt
