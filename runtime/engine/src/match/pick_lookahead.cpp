#include "g2d/pick_lookahead.hpp"

#include <algorithm>

namespace g2d::rt {

namespace {
// What the rewrite of a likely next pick reads beyond its elements, in the
// graphs where IncrementalMatches::prefetch asks for the elements too.
void askData(const RuleSet& rules, std::size_t rule, Match next, const Graph& g) {
    if (g.nodeCapacity() >= IncrementalMatches::kPrefetchMinNodes) rules.prefetchData(rule, next, g);
}
}  // namespace

bool PickLookahead::guessed(Match picked) {
    if (!guessed_[0] && !guessed_[1]) return false;
    ++guesses_;
    const bool hit = picked.nodes == guessed_[0] || picked.nodes == guessed_[1];
    hits_ += hit;
    guessed_[0] = guessed_[1] = nullptr;
    return hit;
}

void PickLookahead::ahead(std::size_t rule, const RuleInfo& info, const MatchSet& set, Match picked, const Rng& rng,
                          const IncrementalMatches& sets, const RuleSet& rules, const Graph& g) {
    // A small set's records stay cached anyway: guessing would only cost.
    if (set.size() < kMinMatches) return;
    if (picksOldest(info.pick)) {
        aheadOldest(rule, info, set, picked, rng, sets, rules, g);
        return;
    }
    // The size the set has at the next picks depends on what those steps
    // add and remove. Most grammars alternate between a few growths (Koch's
    // split adds three matches, or at the last level removes one), so the
    // guesses take the last two distinct growths seen, in every mix.
    const auto size = static_cast<long long>(set.size());
    if (rule == rule_) {
        const long long growth = size - static_cast<long long>(lastSize_);
        if (growth != growth_[0]) {
            growth_[1] = growth_[0];
            growth_[0] = growth;
        }
    } else {
        growth_[0] = growth_[1] = 0;
    }
    rule_ = rule;
    lastSize_ = set.size();
    // The raw draws of the next picks, if they pick from this rule again
    // and nothing else draws (derivation.hpp lists a step's draws).
    Rng future = rng;
    std::uint64_t raw[kAhead];
    for (auto& r : raw) {
        r = future.next();
        if (info.weights.size() > 1) future.unit();
    }
    const long long a = growth_[0], b = growth_[1];
    // The place of the pick `ahead` steps on, had `withB` of the steps
    // between grown by b and the others by a.
    auto position = [&](int ahead, int withB) -> std::size_t {
        const long long sizeThen = size + (ahead - withB) * a + withB * b;
        if (sizeThen <= 1) return 0;
        return static_cast<std::size_t>(Rng::belowFrom(raw[ahead - 1], static_cast<std::uint64_t>(sizeThen)));
    };
    const int mixes = b != a ? 1 : 0;   // 0: one growth, one guess per step
    // Four ahead: the slots.
    for (int k = 0; k <= 4 * mixes; ++k) set.prefetchPosition(position(4, k));
    // Three ahead: the records (their slots were asked for a step ago).
    for (int k = 0; k <= 3 * mixes; ++k) set.prefetchRecordAt(position(3, k));
    // Two ahead: the elements (the record was asked for a step ago), for
    // every guess: for the likeliest only, a third of Koch level 10's
    // rewrites (random picks) still waited for their attribute record, and
    // 40 % of the reads of the next pick's edge here missed the caches
    // (timed by rdtscp); for every guess, 5 % and 10 %.
    for (int k = 0; k <= 2 * mixes; ++k)
        if (const std::size_t at = position(2, k); at < set.size()) sets.prefetch(g, set.at(at), set.nodes(), set.edges());
    // One ahead: what the rewrite reads beyond the elements (asked for a
    // step ago).
    for (int k = 0; k <= mixes; ++k) {
        const std::size_t at = position(1, k);
        if (at >= set.size()) continue;
        const Match next = set.at(at);
        askData(rules, rule, next, g);
        guessed_[k] = next.nodes;
    }
}

// Oldest: each step takes one match of the lowest age group left (drawn
// among them when they tie; a leaver's place goes to the group's last);
// new matches are younger. So the picks ahead come from the lowest groups
// in turn, starting with the one holding this step's pick, less that pick.
// A group's slot is read only once an earlier step asked for it.
void PickLookahead::aheadOldest(std::size_t rule, const RuleInfo& info, const MatchSet& set, Match picked, const Rng& rng,
                                const IncrementalMatches& sets, const RuleSet& rules, const Graph& g) {
    const AgeBuckets& ages = set.ageGroups();
    std::uint64_t groups[kAhead + 1];   // their keys
    const std::size_t count = ages.peekLowest(groups, kAhead + 1);
    if (count == 0) return;
    for (std::size_t i = 1; i < count; ++i) ages.prefetchGroup(groups[i]);
    // The members of the group picks are drawn from, as AgeBuckets will
    // hold them then (ties beyond kTies are left out: a rougher guess).
    constexpr std::size_t kTies = 16;
    std::uint32_t members[kTies];
    std::size_t left = 0;
    auto enter = [&](std::size_t group) {
        const auto ids = ages.groupIds(groups[group]);
        left = std::min(ids.size(), kTies);
        std::copy(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(left), members);
    };
    auto take = [&](std::size_t at) {
        const std::uint32_t id = members[at];
        members[at] = members[--left];
        return id;
    };
    enter(0);
    const std::uint32_t pickedId = set.idOf(picked);
    for (std::size_t i = 0; i < left; ++i)
        if (members[i] == pickedId) {
            take(i);
            break;
        }
    Rng future = rng;
    std::size_t group = 0;
    for (int j = 1; j <= kAhead; ++j) {
        while (left == 0) {
            // The last group's slot is only being asked for now.
            if (++group + 1 >= count) return;
            enter(group);
        }
        const std::size_t at = left > 1 ? static_cast<std::size_t>(future.below(left)) : 0;
        if (info.weights.size() > 1) future.unit();
        const std::uint32_t id = take(at);
        if (j == 1) {   // its elements were asked for a step ago
            const Match next = set.matchOf(id);
            askData(rules, rule, next, g);
            guessed_[0] = next.nodes;
        } else if (j == 2) {   // its record was asked for a step ago
            sets.prefetch(g, set.matchOf(id), set.nodes(), set.edges());
        } else {
            set.prefetchRecord(id);
        }
    }
}

}  // namespace g2d::rt
