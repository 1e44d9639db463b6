#pragma once
// One parallel step of a rule (`parallel`, and every command of a G^3
// command list): a maximal set of non-overlapping matches, all found before
// the step, taken in the order drawn (shuffled, or oldest first), with their
// daughters drawn then, and rewritten in the set's order. Marks are
// step-stamped arrays, so a step costs O(matches).
#include <cstdint>
#include <span>
#include <vector>

#include "g2d/derivation.hpp"
#include "g2d/element_scope.hpp"

namespace g2d::rt {

class ParallelStep {
public:
    // Returns how many matches were rewritten. With `scopes`, the daughter of
    // the set's match i reads the graph within scopes[i] (a compound's,
    // element_scope.hpp).
    std::size_t run(std::size_t rule, const MatchSet& set, RuleSet& rules, Graph& g, Rng& rng, long long step, StepTracer* tracer,
                    const ElementScope* const* scopes = nullptr);
    // A generation (`priority P generation;`): every rule of a priority, in
    // the order given (the grammar's), rewrites its matches (sets[k] of
    // rulesInOrder[k]) in one step. Each rule draws its matches as run()
    // does; a match overlapping one taken before, by this rule or an earlier
    // one, is not rewritten. All read the graph before the step; they are
    // rewritten rule by rule, each rule's in its set's order.
    std::size_t runGeneration(std::span<const std::size_t> rulesInOrder, std::span<const MatchSet* const> sets, RuleSet& rules,
                              Graph& g, Rng& rng, long long step, StepTracer* tracer);
    // Whether the last run rewrote the set's match i (they are rewritten in the set's order).
    bool taken(std::size_t i) const { return i < daughter_.size() && daughter_[i] != kNotTaken; }

private:
    // A little room ahead only: the marks are filled as they grow, and a
    // whole generation's graph is large.
    static void grow(std::vector<std::uint32_t>& v, std::size_t n) {
        if (v.size() < n) v.resize(n + n / 8, 0);
    }
    static constexpr std::uint32_t kNotTaken = 0xffffffffu;
    void beginStep(const Graph& g);
    // Draws `rule`'s matches and takes those that clash with nothing taken
    // this step; daughters[i]: the daughter of the set's match i, or kNotTaken.
    std::size_t claim(std::size_t rule, const MatchSet& set, RuleSet& rules, const Graph& g, Rng& rng,
                      std::vector<std::uint32_t>& daughters);
    void prepareTaken(std::size_t rule, const MatchSet& set, const std::vector<std::uint32_t>& daughters, RuleSet& rules,
                      Graph& g, Rng& rng, long long step, StepTracer* tracer, const ElementScope* const* scopes);
    std::vector<std::uint32_t> order_, daughter_;
    std::vector<std::vector<std::uint32_t>> generation_;   // per rule of a generation: its daughters
    std::vector<long long> sums_;
    // Per element, stamp * 2 if a taken match reads it in this step, stamp *
    // 2 + 1 if one writes it (a match writes only elements it reads).
    std::vector<std::uint32_t> nodeMarks_, edgeMarks_, faceMarks_;
    std::uint32_t stamp_ = 0;
    WriteSet writes_;
    std::vector<double> weights_;   // a match-weighted rule's, per match
};

}  // namespace g2d::rt
