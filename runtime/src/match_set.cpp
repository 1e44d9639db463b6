#include "g2d/match_set.hpp"

#include <algorithm>
#include <stdexcept>

namespace g2d::rt {

MatchSet::MatchSet(int nodes, int edges, bool byAge, std::vector<bool> readsIncidence)
    : nn_(nodes), ne_(edges), width_(static_cast<std::size_t>(nodes + edges)), byAge_(byAge) {
    if (nodes <= 0) throw std::logic_error("a pattern without nodes");
    if (readsIncidence.size() != static_cast<std::size_t>(nodes)) readsIncidence.assign(static_cast<std::size_t>(nodes), true);
    for (bool r : readsIncidence) reads_.push_back(r ? 1 : 0);
}

void MatchSet::add(const std::uint32_t* ids, const Graph& g) { add(ids, ids + nn_, g); }

void MatchSet::add(const NodeId* nodes, const EdgeId* edges, const Graph& g) {
    Id id;
    if (!free_.empty()) {
        id = free_.back();
        free_.pop_back();
    } else {
        id = static_cast<Id>(livePos_.size());
        data_.resize(data_.size() + width_);
        livePos_.push_back(kNoId);
        for (int i = 0; i < nn_; ++i) links_.push_back(Link{kNoId, kNoId});
        if (byAge_) ageSum_.push_back(0);
    }
    std::uint32_t* p = &data_[static_cast<std::size_t>(id) * width_];
    for (int i = 0; i < nn_; ++i) p[i] = nodes[i];
    for (int i = 0; i < ne_; ++i) p[nn_ + i] = edges[i];
    livePos_[id] = static_cast<std::uint32_t>(live_.size());
    live_.push_back(id);
    for (int i = 0; i < nn_; ++i) {
        const NodeId n = p[i];
        auto& heads = headFor(i);
        if (n >= heads.size()) heads.resize(std::max<std::size_t>(g.nodeCapacity(), n + 1) + heads.size() / 2, kNoId);
        const std::uint32_t link = id * static_cast<std::uint32_t>(nn_) + static_cast<std::uint32_t>(i);
        links_[link].next = heads[n];
        links_[link].prev = kNoId;
        if (heads[n] != kNoId) links_[heads[n]].prev = link;
        heads[n] = link;
    }
    if (byAge_) {
        long long sum = 0;
        for (int i = 0; i < nn_; ++i) sum += g.nodeAge(p[i]);
        for (int i = 0; i < ne_; ++i) sum += g.edgeAge(p[nn_ + i]);
        ageSum_[id] = sum;
        ageBuckets_.insert(id, sum);
    }
}

void MatchSet::remove(Id id) {
    const std::uint32_t* p = data(id);
    for (int i = 0; i < nn_; ++i) {
        const std::uint32_t link = id * static_cast<std::uint32_t>(nn_) + static_cast<std::uint32_t>(i);
        if (links_[link].prev != kNoId)
            links_[links_[link].prev].next = links_[link].next;
        else
            headFor(i)[p[i]] = links_[link].next;
        if (links_[link].next != kNoId) links_[links_[link].next].prev = links_[link].prev;
    }
    // Out of the live order: swap with the last.
    const std::uint32_t pos = livePos_[id];
    const Id last = live_.back();
    live_[pos] = last;
    livePos_[last] = pos;
    live_.pop_back();
    livePos_[id] = kNoId;
    if (byAge_) ageBuckets_.erase(id);
    free_.push_back(id);
}

void MatchSet::unlinkAll(NodeId n, GrowArray<std::uint32_t>& heads) {
    if (n >= heads.size()) return;
    while (heads[n] != kNoId) remove(heads[n] / static_cast<std::uint32_t>(nn_));
}

void MatchSet::removeTouching(NodeId n, bool incidenceOnly) {
    unlinkAll(n, head_);
    if (!incidenceOnly) unlinkAll(n, headOther_);
}

void MatchSet::clear() {
    data_.clear();
    livePos_.clear();
    live_.clear();
    free_.clear();
    head_.clear();
    headOther_.clear();
    links_.clear();
    ageSum_.clear();
    ageBuckets_.clear();
}

Match MatchSet::pickRandom(Rng& rng) const {
    if (live_.size() == 1) return view(live_[0]);
    return view(live_[static_cast<std::size_t>(rng.below(live_.size()))]);
}

Match MatchSet::pickOldest(Rng& rng) {
    const auto& bucket = ageBuckets_.lowest();
    if (bucket.size() == 1) return view(bucket[0]);
    return view(bucket[static_cast<std::size_t>(rng.below(bucket.size()))]);
}

std::size_t MatchSet::memoryBytes() const {
    return (data_.capacity() + livePos_.capacity() + live_.capacity() + free_.capacity() + head_.capacity() + headOther_.capacity() +
            links_.capacity() * 2) * 4 + ageSum_.capacity() * 8 + ageBuckets_.memoryBytes();
}

}  // namespace g2d::rt
