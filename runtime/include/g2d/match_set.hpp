#pragma once
// The matches of one rule, kept up to date between steps instead of being
// found again (see derivation.cpp). Stores matches flat, in a deterministic
// order; gives a uniform random match in O(1) and a uniform random oldest
// match in O(log n) (matches bucketed by the sum of their elements' ages).
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/rng.hpp"

namespace g2d::rt {

struct Match {
    std::vector<NodeId> nodes;
    std::vector<EdgeId> edges;
    bool operator==(const Match&) const = default;
};

class MatchSet {
public:
    MatchSet(int nodes, int edges, bool byAge) : nn_(nodes), ne_(edges), byAge_(byAge) {}

    // Adds `m` unless an identical match is already there; returns whether it did.
    bool add(const Match& m, const Graph& g);
    // Removes every match that binds node `n`.
    void removeTouching(NodeId n);
    void clear();

    std::size_t size() const { return live_.size(); }
    bool empty() const { return live_.empty(); }
    Match at(std::size_t i) const { return get(live_[i]); }   // in the set's order
    // A uniform match (one below(n) draw, none when there is one match).
    Match pickRandom(Rng& rng) const;
    // A uniform match among those with the lowest sum of ages (a draw only on ties).
    Match pickOldest(Rng& rng) const;

private:
    using Id = std::uint32_t;
    Match get(Id id) const;
    bool matches(Id id, const Match& m) const;
    std::uint64_t hash(const Match& m) const;
    void unlink(Id id);

    int nn_, ne_;
    bool byAge_;
    std::vector<std::uint32_t> data_;        // per id: nn_ nodes, then ne_ edges
    std::vector<long long> ageSum_;          // per id
    std::vector<std::uint32_t> livePos_;     // per id: position in live_, or kNoId
    std::vector<Id> live_;
    std::vector<Id> free_;
    std::vector<std::vector<Id>> byNode_;    // node -> ids (may hold stale ids)
    std::unordered_multimap<std::uint64_t, Id> byHash_;
    std::map<long long, std::vector<Id>> byAgeSum_;
    std::vector<std::uint32_t> agePos_;      // per id: position in its age bucket
};

}  // namespace g2d::rt
