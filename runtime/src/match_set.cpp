#include "g2d/match_set.hpp"

#include <algorithm>
#include <stdexcept>

namespace g2d::rt {

MatchSet::MatchSet(int nodes, int edges, bool byAge)
    : nn_(nodes), ne_(edges), width_(static_cast<std::size_t>(nodes + edges)), byAge_(byAge) {
    if (nodes <= 0) throw std::logic_error("a pattern without nodes");
}

void MatchSet::add(const std::uint32_t* ids, const Graph& g) {
    Id id;
    if (!free_.empty()) {
        id = free_.back();
        free_.pop_back();
    } else {
        id = static_cast<Id>(livePos_.size());
        data_.resize(data_.size() + width_);
        livePos_.push_back(kNoId);
        next_.resize(next_.size() + static_cast<std::size_t>(nn_));
        prev_.resize(prev_.size() + static_cast<std::size_t>(nn_));
        if (byAge_) ageSum_.push_back(0);
    }
    std::uint32_t* p = &data_[static_cast<std::size_t>(id) * width_];
    std::copy(ids, ids + width_, p);
    livePos_[id] = static_cast<std::uint32_t>(live_.size());
    live_.push_back(id);
    for (int i = 0; i < nn_; ++i) {
        const NodeId n = p[i];
        if (n >= head_.size()) head_.resize(std::max<std::size_t>(g.nodeCapacity(), n + 1) + head_.size() / 2, kNoId);
        const std::uint32_t link = id * static_cast<std::uint32_t>(nn_) + static_cast<std::uint32_t>(i);
        next_[link] = head_[n];
        prev_[link] = kNoId;
        if (head_[n] != kNoId) prev_[head_[n]] = link;
        head_[n] = link;
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
        if (prev_[link] != kNoId)
            next_[prev_[link]] = next_[link];
        else
            head_[p[i]] = next_[link];
        if (next_[link] != kNoId) prev_[next_[link]] = prev_[link];
    }
    // Out of the live order: swap with the last.
    const std::uint32_t pos = livePos_[id];
    const Id last = live_.back();
    live_[pos] = last;
    livePos_[last] = pos;
    live_.pop_back();
    livePos_[id] = kNoId;
    if (byAge_) ageBuckets_.erase(id, ageSum_[id]);
    free_.push_back(id);
}

void MatchSet::removeTouching(NodeId n) {
    if (n >= head_.size()) return;
    while (head_[n] != kNoId) remove(head_[n] / static_cast<std::uint32_t>(nn_));
}

void MatchSet::clear() {
    data_.clear();
    livePos_.clear();
    live_.clear();
    free_.clear();
    head_.clear();
    next_.clear();
    prev_.clear();
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
    return (data_.capacity() + livePos_.capacity() + live_.capacity() + free_.capacity() + head_.capacity() +
            next_.capacity() + prev_.capacity()) * 4 + ageSum_.capacity() * 8 + ageBuckets_.memoryBytes();
}

}  // namespace g2d::rt
