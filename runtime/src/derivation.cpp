#include "g2d/derivation.hpp"

#include "g2d/deadline.hpp"
#include "g2d/incremental_matches.hpp"
#include "g2d/node_merge.hpp"
#include "g2d/pick_lookahead.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <numeric>
#include <optional>

namespace g2d::rt {

long long ageSum(Match m, int nodes, int edges, const Graph& g, int faces) {
    long long sum = 0;
    for (int i = 0; i < nodes; ++i) sum += g.nodeAge(m.nodes[i]);
    for (int i = 0; i < edges; ++i) sum += g.edgeAge(m.edges[i]);
    for (int i = 0; i < faces; ++i) sum += g.faceAge(m.faces[i]);
    return sum;
}

std::size_t pickDaughter(const std::vector<double>& weights, Rng& rng) {
    if (weights.size() <= 1) return 0;
    const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
    const double u = rng.unit() * total;
    double cumulative = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        cumulative += weights[i];
        if (u < cumulative) return i;
    }
    return weights.size() - 1;
}

namespace {

RunawayError timeLimit(const DerivationOptions& limits, long long step) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g s", limits.timeoutSeconds.value_or(0));
    return RunawayError("time_limit", std::string("the derivation ran past the time limit of ") + seconds + " at step " +
                                          std::to_string(step) + " (raise --timeout)");
}

struct Group {
    long long priority;
    std::vector<std::size_t> rules;
    std::optional<long long> limit;
    long long applied = 0;
};

// Applies a maximal set of non-overlapping matches, all found before the
// step: taken in the order drawn (shuffled, or oldest first), with their
// daughters drawn then, and rewritten in the set's order. Marks are
// step-stamped arrays, so a step costs O(matches).
class ParallelStep {
public:
    // Returns how many matches were rewritten.
    std::size_t run(std::size_t rule, const MatchSet& set, RuleSet& rules, Graph& g, Rng& rng, long long step,
                    StepTracer* tracer) {
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
            rules.prepare(rule, daughter_[i], m, g, rng, step);
        }
        rules.commit(g, step);
        return taken;
    }

private:
    // A little room ahead only: the marks are filled as they grow, and a
    // whole generation's graph is large.
    static void grow(std::vector<std::uint32_t>& v, std::size_t n) {
        if (v.size() < n) v.resize(n + n / 8, 0);
    }
    static constexpr std::uint32_t kNotTaken = 0xffffffffu;
    std::vector<std::uint32_t> order_, daughter_;
    std::vector<long long> sums_;
    // Per element, stamp * 2 if a taken match reads it in this step, stamp *
    // 2 + 1 if one writes it (a match writes only elements it reads).
    std::vector<std::uint32_t> nodeMarks_, edgeMarks_, faceMarks_;
    std::uint32_t stamp_ = 0;
    WriteSet writes_;
};

}  // namespace

namespace {

// Fills in the statistics however the derivation ends (returning or throwing).
class ResultSummary {
public:
    ResultSummary(DerivationResult& result, const PickLookahead& lookahead)
        : result_(result), lookahead_(lookahead), start_(std::chrono::steady_clock::now()) {}
    ~ResultSummary() {
        result_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        result_.lookaheadGuesses = lookahead_.guesses();
        result_.lookaheadHits = lookahead_.hits();
        if (sets_) {
            result_.setRepairs = static_cast<long long>(sets_->setsRepaired());
            result_.setRepairsSkipped = static_cast<long long>(sets_->setsSkipped());
        }
    }
    void follow(const IncrementalMatches& sets) { sets_ = &sets; }

private:
    DerivationResult& result_;
    const PickLookahead& lookahead_;
    const IncrementalMatches* sets_ = nullptr;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace

void derive(Graph& g, RuleSet& rules, Rng& rng, const DerivationOptions& limits, DerivationResult& result,
            const StepObserver& observer, StepTracer* tracer) {
    result = DerivationResult{};
    std::map<long long, Group> byPriority;
    bool neighbours = false;
    for (std::size_t r = 0; r < rules.ruleCount(); ++r) neighbours = neighbours || rules.info(r).readsNeighbours;
    g.trackNeighbours(neighbours);
    for (std::size_t r = 0; r < rules.ruleCount(); ++r) {
        const long long p = rules.info(r).priority;
        auto& grp = byPriority[p];
        grp.priority = p;
        grp.rules.push_back(r);
    }
    std::vector<Group> groups;
    for (auto& [p, grp] : byPriority) {
        if (auto it = limits.perPriority.find(p); it != limits.perPriority.end()) grp.limit = it->second;
        groups.push_back(std::move(grp));
    }

    std::vector<std::size_t> order;
    ParallelStep parallel;
    PickLookahead lookahead;
    std::optional<IncrementalMatches> found;   // before the summary, which reads it as it goes
    ResultSummary summary(result, lookahead);
    std::optional<DeadlineWatch> deadline;
    if (limits.timeoutSeconds) deadline.emplace(*limits.timeoutSeconds);
    try {
        found.emplace(rules, g);
    } catch (const DeadlinePassed&) {
        throw timeLimit(limits, 0);
    }
    IncrementalMatches& sets = *found;
    summary.follow(sets);
    // A priority whose limit is used up never applies again: its rules' sets
    // are no longer kept (mutex STS: the requests, once every process made one).
    auto retireIfSpent = [&](const Group& grp) {
        if (grp.limit && grp.applied >= *grp.limit)
            for (std::size_t r : grp.rules) sets.retire(r);
    };
    for (const auto& grp : groups) retireIfSpent(grp);
    g.forgetChanges();
    // Merging keeps a spatial index of the nodes from the start when some rule merges.
    std::optional<NodeMerger> merger;
    for (std::size_t r = 0; r < rules.ruleCount(); ++r)
        if (const double tolerance = rules.info(r).mergeTolerance; tolerance > 0 && !merger)
            merger.emplace(g, 4 * tolerance, [&](Graph& graph, FaceId from, FaceId to) { rules.copyFaceAttributes(graph, from, to); });
    // After a rule's step: merging (if the rule merges), then the match sets
    // are brought up to date, reading the step's changes in place; they are
    // forgotten after it (before a full search, which reads none: a
    // generation's marks are still in the caches now).
    auto afterStep = [&](std::size_t r, std::size_t daughter, long long step, EdgeId newEdgesFrom, NodeId newNodesFrom) {
        if (merger) {
            merger->sync(g);
            if (const double tolerance = rules.info(r).mergeTolerance; tolerance > 0) merger->mergeChanged(g, tolerance);
        }
        const bool everything = IncrementalMatches::searchesEverything(g);
        if (everything) g.forgetChanges();
        try {
            sets.update(g, newEdgesFrom, newNodesFrom, everything, r, daughter);
        } catch (const DeadlinePassed&) {
            // While finding matches after the step: the step itself is complete.
            result.steps = step;
            if (tracer) tracer->stepDone(step, g);
            if (observer) observer(step, g);
            throw timeLimit(limits, step);
        }
        if (!everything) g.forgetChanges();
        if (limits.verifyMatches) sets.verify(g, step);
    };
    auto stepDone = [&](long long step) {
        result.steps = step;
        if (tracer) tracer->stepDone(step, g);
        if (observer) observer(step, g);
        if (deadlineHasPassed()) throw timeLimit(limits, step);
        if (g.nodeCount() + g.edgeCount() > limits.maxElements)
            throw RunawayError("element_limit", "the graph grew past " + std::to_string(limits.maxElements) + " elements at step " +
                               std::to_string(step) + " (a runaway derivation? set a `limit`, or raise --max-elements)");
    };
    if (!rules.sequence().empty()) {
        // A command list: step k applies command k to all its matches (none: the graph stays as it is).
        for (std::size_t r : rules.sequence()) {
            if (limits.steps && result.steps >= *limits.steps) {
                result.stopped = StopReason::StepLimit;
                return;
            }
            const long long step = result.steps + 1;
            const auto newEdgesFrom = static_cast<EdgeId>(g.edgeCapacity());
            const auto newNodesFrom = static_cast<NodeId>(g.nodeCapacity());
            const MatchSet& set = sets.of(r);
            if (!set.empty()) {
                try {
                    result.applications += static_cast<long long>(parallel.run(r, set, rules, g, rng, step, tracer));
                } catch (const DeadlinePassed&) {
                    throw timeLimit(limits, step);
                }
                afterStep(r, IncrementalMatches::kAnyDaughter, step, newEdgesFrom, newNodesFrom);
            }
            stepDone(step);
        }
        result.stopped = StopReason::Terminal;
        return;
    }
    while (true) {
        if (limits.steps && result.steps >= *limits.steps) {
            result.stopped = StopReason::StepLimit;
            break;
        }
        const long long step = result.steps + 1;
        const auto newEdgesFrom = static_cast<EdgeId>(g.edgeCapacity());   // ids are never reused
        const auto newNodesFrom = static_cast<NodeId>(g.nodeCapacity());
        bool applied = false;
        for (auto& grp : groups) {
            if (grp.limit && grp.applied >= *grp.limit) continue;
            // Rules of one priority are tried in random order (a group of
            // one needs no copy: shuffling it draws nothing).
            const std::vector<std::size_t>* tryOrder = &grp.rules;
            if (grp.rules.size() > 1) {
                order = grp.rules;
                shuffle(order, rng);
                tryOrder = &order;
            }
            for (std::size_t r : *tryOrder) {
                MatchSet& set = sets.of(r);
                if (set.empty()) continue;
                const RuleInfo& info = rules.info(r);
                std::size_t daughter = IncrementalMatches::kAnyDaughter;
                try {
                    if (info.parallel) {
                        result.applications += static_cast<long long>(parallel.run(r, set, rules, g, rng, step, tracer));
                    } else {
                        const Match m = info.pick == Pick::Oldest ? set.pickOldest(rng) : set.pickRandom(rng);
                        if (!lookahead.guessed(m)) sets.prefetch(g, m, set.nodes(), set.edges());
                        const std::size_t d = pickDaughter(info.weights, rng);
                        daughter = d;
                        lookahead.ahead(r, info, set, m, rng, sets, rules, g);
                        if (tracer) tracer->applying(r, d, m, g);
                        rules.prepare(r, d, m, g, rng, step);
                        rules.commit(g, step);
                        ++result.applications;
                    }
                } catch (const DeadlinePassed&) {
                    // Inside the step (a grammar function ran long): the graph is
                    // still the one of the last completed step.
                    throw timeLimit(limits, step);
                }
                ++grp.applied;
                retireIfSpent(grp);   // before the repair: a spent rule needs none
                afterStep(r, daughter, step, newEdgesFrom, newNodesFrom);
                applied = true;
                break;
            }
            if (applied) break;
        }
        if (!applied) {
            result.stopped = StopReason::Terminal;
            break;
        }
        stepDone(step);
    }
}

}  // namespace g2d::rt
