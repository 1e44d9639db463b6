#pragma once
// G^3's compound commands (Laganeckiene 2012, §3.3) in a command list.
//
// A compound's initial primitives are the matches of its match rule, found
// when the list reaches it. Each gets a scope (element_scope.hpp): the
// matched primitive and those under it. The compound's entries then run in
// lock-step, one step each, for all its instances at once:
//   * a rule: for every instance, its matches on the graph with the scope
//     set (so topological facts count the scope only) whose elements all lie
//     in the scope; the daughter reads within the scope too (the first one
//     the match was found in); a match found in several scopes is one application
//     (§3.3.3), and what it creates joins every one of them (and, up the
//     stack, their compounds' scopes, §3.3.5). They are rewritten as one
//     parallel step;
//   * a compound: its instances are found the same way within each scope
//     (one found in two scopes belongs to both), and its entries run in turn.
// An instance's lets are evaluated when it is found, within its own scope.
// Every entry is a step, with or without instances, so `age` counts
// commands whatever matched.
#include <deque>
#include <functional>
#include <map>
#include <vector>

#include "g2d/element_scope.hpp"
#include "g2d/parallel_step.hpp"

namespace g2d::rt {

class CompoundRun {
public:
    // What the derivation does around a step: whether one more may start
    // (limits), and after it (merging, match sets, counters).
    struct Hooks {
        std::function<bool()> mayStep;
        std::function<long long()> nextStep;   // the number of the step about to start
        // Rewrites `set` as one parallel step (with `parallel`, reading
        // match i within scopes[i]): how many were applied.
        std::function<std::size_t(std::size_t rule, const MatchSet& set, long long step, const ElementScope* const* scopes)> apply;
        std::function<void(std::size_t rule, long long step, EdgeId newEdgesFrom, NodeId newNodesFrom)> afterStep;
        std::function<void(long long step)> stepDone;
        std::function<void()> foundNone;   // a compound found no instance (--stats)
    };
    // `parallel` is the step Hooks::apply runs (which matches it took);
    // `repeatCounts` the counts of the lists' repeats (SequenceEntry::Repeat).
    CompoundRun(Graph& g, RuleSet& rules, Rng& rng, const ParallelStep& parallel, Hooks hooks, const std::vector<long long>& repeatCounts)
        : g_(g), rules_(rules), rng_(rng), parallel_(parallel), hooks_(std::move(hooks)), counts_(repeatCounts) {}

    // Runs compound `c` from its initial primitives `initial` (its match
    // rule's matches). False when a limit stopped it. `applications` counts
    // the rewrites.
    bool run(std::size_t c, const MatchSet& initial, long long& applications);

private:
    struct Instance {
        ElementScope scope;
        std::vector<std::size_t> parents;
    };
    bool runEntries(std::size_t c, const std::vector<std::size_t>& instances, long long& applications);
    // The matches of `rule` within each instance's scope, each once, with the instances it was found in.
    void scopedMatches(std::size_t rule, const std::vector<std::size_t>& instances, MatchSet& set,
                       std::vector<std::vector<std::size_t>>& owners);
    // An instance of compound `c` at match `m` of its match rule: its scope, and its lets' values read within it.
    std::size_t newInstance(std::size_t c, Match m, int nodes, int edges, int faces, std::vector<std::size_t> parents);
    void addToScopes(std::size_t instance, ElemClass c, std::uint32_t from, std::uint32_t to);

    Graph& g_;
    RuleSet& rules_;
    Rng& rng_;
    const ParallelStep& parallel_;
    Hooks hooks_;
    const std::vector<long long>& counts_;
    std::deque<Instance> instances_;
    MatchBuffer buffer_;
};

}  // namespace g2d::rt
