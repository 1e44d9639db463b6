#include "g2d/derivation.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <numeric>
#include <unordered_set>

namespace g2d::rt {

long long ageSum(const Match& m, const Graph& g) {
    long long sum = 0;
    for (NodeId n : m.nodes) sum += g.nodeAge(n);
    for (EdgeId e : m.edges) sum += g.edgeAge(e);
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

struct Group {
    long long priority;
    std::vector<std::size_t> rules;
    std::optional<long long> limit;
    long long applied = 0;
};

// Applies a maximal set of non-overlapping matches, all found before the step.
void parallelStep(std::size_t rule, std::vector<Match>& matches, RuleSet& rules, Graph& g, Rng& rng,
                  long long step) {
    const RuleInfo& info = rules.info(rule);
    if (info.pick == Pick::Random) {
        shuffle(matches, rng);
    } else {
        std::vector<long long> sums(matches.size());
        for (std::size_t i = 0; i < matches.size(); ++i) sums[i] = ageSum(matches[i], g);
        std::vector<std::size_t> order(matches.size());
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return sums[a] < sums[b]; });
        std::vector<Match> sorted;
        sorted.reserve(matches.size());
        for (std::size_t i : order) sorted.push_back(std::move(matches[i]));
        matches = std::move(sorted);
    }
    std::unordered_set<NodeId> readNodes, writtenNodes;
    std::unordered_set<EdgeId> readEdges, writtenEdges;
    for (const Match& m : matches) {
        bool clash = false;
        for (NodeId n : m.nodes) clash = clash || writtenNodes.count(n);
        for (EdgeId e : m.edges) clash = clash || writtenEdges.count(e);
        if (clash) continue;
        const std::size_t daughter = pickDaughter(info.weights, rng);
        const WriteSet w = rules.writeSet(rule, daughter, m);
        for (NodeId n : w.nodes) clash = clash || readNodes.count(n);
        for (EdgeId e : w.edges) clash = clash || readEdges.count(e);
        if (clash) continue;
        readNodes.insert(m.nodes.begin(), m.nodes.end());
        readEdges.insert(m.edges.begin(), m.edges.end());
        writtenNodes.insert(w.nodes.begin(), w.nodes.end());
        writtenEdges.insert(w.edges.begin(), w.edges.end());
        rules.prepare(rule, daughter, m, g, rng, step);
    }
    rules.commit(g, step);
}

}  // namespace

// The nodes within `radius` edges of the changed ones (changed ones first).
std::vector<NodeId> region(const Graph& g, const std::vector<NodeId>& changed, int radius,
                           std::vector<std::uint32_t>& seen, std::uint32_t mark) {
    std::vector<NodeId> out;
    if (seen.size() < g.nodeCapacity()) seen.resize(g.nodeCapacity(), 0);
    for (NodeId n : changed)
        if (seen[n] != mark) {
            seen[n] = mark;
            out.push_back(n);
        }
    std::size_t begin = 0;
    for (int d = 0; d < radius; ++d) {
        const std::size_t end = out.size();
        for (std::size_t i = begin; i < end; ++i) {
            const NodeId n = out[i];
            if (!g.nodeAlive(n)) continue;
            for (EdgeId e : g.incident(n)) {
                const NodeId o = g.source(e) == n ? g.target(e) : g.source(e);
                if (seen[o] != mark) {
                    seen[o] = mark;
                    out.push_back(o);
                }
            }
        }
        begin = end;
    }
    return out;
}

// Repairs every rule's matches around what the last step changed.
class IncrementalMatches {
public:
    IncrementalMatches(RuleSet& rules, const Graph& g) : rules_(rules) {
        for (std::size_t r = 0; r < rules.ruleCount(); ++r) {
            const RuleInfo& info = rules.info(r);
            sets_.emplace_back(static_cast<int>(info.nodeKinds.size()), info.edgeCount, info.pick == Pick::Oldest);
            std::vector<Match> all;
            rules.findMatches(r, g, all);
            for (const Match& m : all) sets_.back().add(m, g);
        }
    }

    MatchSet& of(std::size_t rule) { return sets_[rule]; }

    // With G2D_VERIFY_MATCHES set (the tests set it): every rule's set must
    // hold exactly the matches a full search finds.
    void verify(const Graph& g, long long step) {
        std::vector<Match> all;
        for (std::size_t r = 0; r < sets_.size(); ++r) {
            all.clear();
            rules_.findMatches(r, g, all);
            std::vector<Match> kept;
            for (std::size_t i = 0; i < sets_[r].size(); ++i) kept.push_back(sets_[r].at(i));
            auto key = [](const Match& m) { return std::make_pair(m.nodes, m.edges); };
            auto less = [&](const Match& a, const Match& b) { return key(a) < key(b); };
            std::sort(all.begin(), all.end(), less);
            std::sort(kept.begin(), kept.end(), less);
            if (all != kept)
                throw std::logic_error("incremental matching lost track of rule " + std::to_string(r) + " after step " +
                                       std::to_string(step) + ": " + std::to_string(kept.size()) + " matches kept, " +
                                       std::to_string(all.size()) + " found");
        }
    }

    void update(const Graph& g, const std::vector<NodeId>& changed) {
        if (changed.empty()) return;
        std::vector<Match> found;
        for (std::size_t r = 0; r < sets_.size(); ++r) {
            const RuleInfo& info = rules_.info(r);
            const auto area = region(g, changed, info.radius, seen_, ++mark_);
            MatchSet& set = sets_[r];
            for (NodeId n : area) set.removeTouching(n);
            for (NodeId h : area) {
                if (!g.nodeAlive(h)) continue;
                for (std::size_t p = 0; p < info.nodeKinds.size(); ++p) {
                    const int kind = info.nodeKinds[p];
                    if (kind >= 0 && kind != g.nodeKind(h)) continue;
                    found.clear();
                    rules_.findAnchored(r, g, static_cast<int>(p), h, found);
                    for (const Match& m : found) set.add(m, g);
                }
            }
        }
    }

private:
    RuleSet& rules_;
    std::vector<MatchSet> sets_;
    std::vector<std::uint32_t> seen_;
    std::uint32_t mark_ = 0;
};

DerivationResult derive(Graph& g, RuleSet& rules, Rng& rng, const DerivationLimits& limits,
                        const StepObserver& observer) {
    const auto start = std::chrono::steady_clock::now();
    std::map<long long, Group> byPriority;
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

    DerivationResult result;
    std::vector<Match> matches;
    std::vector<std::size_t> order;
    IncrementalMatches sets(rules, g);
    g.takeDirty();
    static const bool verify = std::getenv("G2D_VERIFY_MATCHES") != nullptr;
    while (true) {
        if (limits.steps && result.steps >= *limits.steps) {
            result.stopped = StopReason::StepLimit;
            break;
        }
        const long long step = result.steps + 1;
        bool applied = false;
        for (auto& grp : groups) {
            if (grp.limit && grp.applied >= *grp.limit) continue;
            order = grp.rules;
            shuffle(order, rng);
            for (std::size_t r : order) {
                MatchSet& set = sets.of(r);
                if (set.empty()) continue;
                const RuleInfo& info = rules.info(r);
                if (info.parallel) {
                    matches.clear();
                    for (std::size_t i = 0; i < set.size(); ++i) matches.push_back(set.at(i));
                    parallelStep(r, matches, rules, g, rng, step);
                } else {
                    const Match m = info.pick == Pick::Oldest ? set.pickOldest(rng) : set.pickRandom(rng);
                    const std::size_t d = pickDaughter(info.weights, rng);
                    rules.prepare(r, d, m, g, rng, step);
                    rules.commit(g, step);
                }
                sets.update(g, g.takeDirty());
                if (verify) sets.verify(g, step);
                applied = true;
                ++grp.applied;
                break;
            }
            if (applied) break;
        }
        if (!applied) {
            result.stopped = StopReason::Terminal;
            break;
        }
        result.steps = step;
        if (g.nodeCount() + g.edgeCount() > limits.maxElements)
            throw RunawayError("the graph grew past " + std::to_string(limits.maxElements) + " elements at step " +
                               std::to_string(step) + " (a runaway derivation? set a `limit`)");
        if (observer) observer(step, g);
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace g2d::rt
