#include "g2d/derivation.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_set>

namespace g2d::rt {

long long ageSum(const Match& m, const Graph& g) {
    long long sum = 0;
    for (NodeId n : m.nodes) sum += g.nodeAge(n);
    for (EdgeId e : m.edges) sum += g.edgeAge(e);
    return sum;
}

std::size_t pickMatch(const std::vector<Match>& matches, Pick pick, const Graph& g, Rng& rng) {
    if (matches.size() == 1) return 0;
    if (pick == Pick::Random) return static_cast<std::size_t>(rng.below(matches.size()));
    // Oldest: the lowest mean creation step. Matches of one rule have the same
    // number of elements, so comparing sums is exact.
    std::vector<std::size_t> oldest;
    long long best = 0;
    for (std::size_t i = 0; i < matches.size(); ++i) {
        const long long s = ageSum(matches[i], g);
        if (oldest.empty() || s < best) { oldest.assign(1, i); best = s; }
        else if (s == best) oldest.push_back(i);
    }
    if (oldest.size() == 1) return oldest[0];
    return oldest[static_cast<std::size_t>(rng.below(oldest.size()))];
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
                matches.clear();
                rules.findMatches(r, g, matches);
                if (matches.empty()) continue;
                const RuleInfo& info = rules.info(r);
                if (info.parallel) {
                    parallelStep(r, matches, rules, g, rng, step);
                } else {
                    const std::size_t m = pickMatch(matches, info.pick, g, rng);
                    const std::size_t d = pickDaughter(info.weights, rng);
                    rules.prepare(r, d, matches[m], g, rng, step);
                    rules.commit(g, step);
                }
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
