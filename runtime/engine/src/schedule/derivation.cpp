#include "g2d/derivation.hpp"

#include <numeric>


namespace g2d::rt {

std::size_t pickDaughter(const std::vector<double>& weights, Rng& rng) {
    if (weights.size() <= 1) return 0;
    const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
    const double u = rng.unit() * total;
    double cumulative = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        cumulative += weights[i];
        if (u < cumulative) return i;
    }
    // u rounded up to the total: the last daughter that can be chosen.
    std::size_t last = weights.size() - 1;
    while (last > 0 && !(weights[last] > 0)) --last;
    return last;
}

std::size_t chooseDaughter(RuleSet& rules, std::size_t rule, const RuleInfo& info, Match m, const Graph& g, Rng& rng,
                           std::vector<double>& scratch) {
    if (!info.matchWeighted) return pickDaughter(info.weights, rng);
    scratch = info.weights;
    rules.weigh(rule, m, g, scratch);
    return pickDaughter(scratch, rng);
}

}  // namespace g2d::rt
