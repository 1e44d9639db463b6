#include "g2d/parallel_step.hpp"

#include <algorithm>
#include <numeric>

namespace g2d::rt {

std::size_t ParallelStep::run(std::size_t rule, const MatchSet& set, RuleSet& rules, Graph& g, Rng& rng, long long step,
                               StepTracer* tracer, const ElementScope* const* scopes) {
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
        for (std::size_t i = 0; i < set.size(); ++i) sums_[i] = set.ageSumAt(i);
        std::stable_sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) { return sums_[a] < sums_[b]; });
    }
    if (++stamp_ >= 0x7fffffffu) {   // about to wrap: forget every old mark
        for (auto* v : {&nodeMarks_, &edgeMarks_, &faceMarks_}) std::fill(v->begin(), v->end(), 0);
        stamp_ = 1;
    }
    grow(nodeMarks_, g.nodeCapacity());
    grow(edgeMarks_, g.edgeCapacity());
    grow(faceMarks_, g.faceCapacity());
    const std::uint32_t read = stamp_ * 2, written = stamp_ * 2 + 1;
    // daughter_[i]: the daughter drawn for the set's match i, kNotTaken if it is not rewritten.
    daughter_.assign(set.size(), kNotTaken);
    std::size_t taken = 0;
    for (std::uint32_t i : order_) {
        const Match m = set.at(i);
        bool clash = false;
        for (int k = 0; k < nn; ++k) clash = clash || nodeMarks_[m.nodes[k]] == written;
        for (int k = 0; k < ne; ++k) clash = clash || edgeMarks_[m.edges[k]] == written;
        for (int k = 0; k < nf; ++k) clash = clash || faceMarks_[m.faces[k]] == written;
        if (clash) continue;
        const std::size_t daughter = pickDaughter(info.weights, rng);
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
        daughter_[i] = static_cast<std::uint32_t>(daughter);
        ++taken;
    }
    // Rewrite the taken matches in the set's order, not the draw's: the
    // set holds them roughly as the graph stores their elements, so the
    // rewrite walks memory forward instead of jumping across it.
    for (std::size_t i = 0; i < daughter_.size(); ++i) {
        if (daughter_[i] == kNotTaken) continue;
        const Match m = set.at(i);
        if (tracer) tracer->applying(rule, daughter_[i], m, g);
        if (scopes) g.setScope(scopes[i]);
        rules.prepare(rule, daughter_[i], m, g, rng, step);
    }
    g.setScope(nullptr);
    rules.commit(g, step);
    return taken;
}

}  // namespace g2d::rt
