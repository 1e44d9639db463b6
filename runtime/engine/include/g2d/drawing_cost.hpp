#pragma once
// `layout angles { cost = …; temperature = …; }`: Metropolis acceptance of
// proposals (Merrell 2023 §6.3, requirement 4). A cost reads counts of the
// graph — elements of a kind, all nodes, all edges — which the derivation
// keeps up to date from each application's DaughterShape, so a proposal's
// cost is known before it is drawn.
#include <cstddef>
#include <vector>

#include "g2d/angle_step.hpp"
#include "g2d/graph.hpp"
#include "g2d/match_set.hpp"

namespace g2d::rt {

// What `count(K)`, `nodes` and `edges` read: per kind index, then all nodes, then all edges.
class KindCounts {
public:
    static constexpr int kNodes = -1, kEdges = -2;   // the indices of `nodes` and `edges`

    explicit KindCounts(std::size_t kinds = 0) : perKind_(kinds + 2, 0) {}
    // The counts of g's live nodes and edges.
    static KindCounts of(const Graph& g, std::size_t kinds);
    // `count(K)` for kind index >= 0, `nodes` for kNodes, `edges` for kEdges.
    long long operator[](int index) const { return perKind_[slot(index)]; }
    void add(int index, long long n) { perKind_[slot(index)] += n; }
    std::size_t kinds() const { return perKind_.size() - 2; }

private:
    std::size_t slot(int index) const {
        return index >= 0 ? static_cast<std::size_t>(index) : perKind_.size() - static_cast<std::size_t>(-index);
    }
    std::vector<long long> perKind_;
};

// The counts after applying `shape` at `m` (node and edge kinds alike; the
// edges of a deleted node go with it).
void countChange(const Graph& g, const DaughterShape& shape, Match m, KindCounts& counts);

// The Metropolis test: a proposal whose cost changes by `delta` is accepted
// when delta <= 0 (nothing drawn), else when Rng::unit() < exp(-delta / temperature).
bool metropolisAccepts(double delta, double temperature, Rng& rng);

}  // namespace g2d::rt
