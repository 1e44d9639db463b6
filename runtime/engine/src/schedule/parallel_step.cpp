#include "g2d/parallel_step.hpp"

#include <algorithm>
#include <numeric>

namespace g2d::rt {

void ParallelStep::beginStep(const Graph& g) {
    if (++stamp_ >= 0x7fffffffu) {   // about to wrap: forget every old mark
        for (auto* v : {&nodeMarks_, &edgeMarks_, &faceMarks_}) std::fill(v->begin(), v->end(), 0);
        stamp_ = 1;
    }
    grow(nodeMarks_, g.nodeCapacity());
    grow(edgeMarks_, g.edgeCapacity());
    grow(faceMarks_, g.faceCapacity());
}

std::size_t ParallelStep::claim(std::size_t rule, const MatchSet& set, RuleSet& rules, const Graph& g, Rng& rng,
                                std::vector<std::uint32_t>& daughters) {
    const RuleInfo& info = rules.info(rule);
    const int nn = set.nodes(), ne = set.edges(), nf = set.faces();
    // The matches are read in place: the set is repaired only after
    // commit(), so the views the rules keep until then stay valid.
    order_.resize(set.size());
    std::iota(order_.begin(), order_.end(), 0);
    if (info.pick == Pick::Random) {
        shuffle(order_, rng);
    } else {
        sums_.resize(set.size());
        for (std::size_t i = 0; i < set.size(); ++i) sums_[i] = set.oldestKeyAt(i);
        std::stable_sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) { return sums_[a] < sums_[b]; });
    }
    const std::uint32_t read = stamp_ * 2, written = stamp_ * 2 + 1;
    // daughters[i]: the daughter drawn for the set's match i, kNotTaken if it is not rewritten.
    daughters.assign(set.size(), kNotTaken);
    std::size_t taken = 0;
    for (std::uint32_t i : order_) {
        const Match m = set.at(i);
        bool clash = false;
        for (int k = 0; k < nn; ++k) clash = clash || nodeMarks_[m.nodes[k]] == written;
        for (int k = 0; k < ne; ++k) clash = clash || edgeMarks_[m.edges[k]] == written;
        for (int k = 0; k < nf; ++k) clash = clash || faceMarks_[m.faces[k]] == written;
        if (clash) continue;
        const std::size_t daughter = chooseDaughter(rules, rule, info, m, g, rng, weights_);
        writes_.clear();
        rules.writeSet(rule, daughter, m, writes_);
        for (NodeId n : writes_.nodes) clash = clash || (nodeMarks_[n] >> 1) == stamp_;
        for (EdgeId e : writes_.edges) clash = clash || (edgeMarks_[e] >> 1) == stamp_;
        for (FaceId f : writes_.faces) clash = clash || (faceMarks_[f] >> 1) == stamp_;
        if (clash) continue;
        for (int k = 0; k < nn; ++k) nodeMarks_[m.nodes[k]] = read;   // none was written (no clash)
        for (int k = 0; k < ne; ++k) edgeMarks_[m.edges[k]] = read;
        for (int k = 0; k < nf; ++k) faceMarks_[m.faces[k]] = read;
        for (NodeId n : writes_.nodes) nodeMarks_[n] = written;
        for (EdgeId e : writes_.edges) edgeMarks_[e] = written;
        for (FaceId f : writes_.faces) faceMarks_[f] = written;
        daughters[i] = static_cast<std::uint32_t>(daughter);
        ++taken;
    }
    return taken;
}

// Prepares the taken matches in the set's order, not the draw's: the set
// holds them roughly as the graph stores their elements, so the rewrite
// walks memory forward instead of jumping across it.
void ParallelStep::prepareTaken(std::size_t rule, const MatchSet& set, const std::vector<std::uint32_t>& daughters,
                                RuleSet& rules, Graph& g, Rng& rng, long long step, StepTracer* tracer,
                                const ElementScope* const* scopes) {
    for (std::size_t i = 0; i < daughters.size(); ++i) {
        if (daughters[i] == kNotTaken) continue;
        const Match m = set.at(i);
        if (tracer) tracer->applying(rule, daughters[i], m, g);
        if (scopes) g.setScope(scopes[i]);
        rules.prepareApplication(rule, daughters[i], m, g, rng, step);
    }
    g.setScope(nullptr);
}

std::size_t ParallelStep::run(std::size_t rule, const MatchSet& set, RuleSet& rules, Graph& g, Rng& rng, long long step,
                               StepTracer* tracer, const ElementScope* const* scopes) {
    beginStep(g);
    const std::size_t taken = claim(rule, set, rules, g, rng, daughter_);
    prepareTaken(rule, set, daughter_, rules, g, rng, step, tracer, scopes);
    rules.commit(g, step);
    return taken;
}

std::size_t ParallelStep::runGeneration(std::span<const std::size_t> rulesInOrder, std::span<const MatchSet* const> sets,
                                        RuleSet& rules, Graph& g, Rng& rng, long long step, StepTracer* tracer) {
    beginStep(g);
    daughter_.clear();   // taken() describes single-rule runs only
    if (generation_.size() < rulesInOrder.size()) generation_.resize(rulesInOrder.size());
    std::size_t taken = 0;
    // Earlier rules claim first: a match that overlaps one an earlier rule
    // took is not rewritten (docs/language.md §12.5).
    for (std::size_t k = 0; k < rulesInOrder.size(); ++k) taken += claim(rulesInOrder[k], *sets[k], rules, g, rng, generation_[k]);
    for (std::size_t k = 0; k < rulesInOrder.size(); ++k)
        prepareTaken(rulesInOrder[k], *sets[k], generation_[k], rules, g, rng, step, tracer, nullptr);
    rules.commit(g, step);
    return taken;
}

}  // namespace g2d::rt
