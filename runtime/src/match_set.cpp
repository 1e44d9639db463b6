#include "g2d/match_set.hpp"

#include <algorithm>

namespace g2d::rt {

Match MatchSet::get(Id id) const {
    Match m;
    const std::uint32_t* p = &data_[static_cast<std::size_t>(id) * (nn_ + ne_)];
    m.nodes.assign(p, p + nn_);
    m.edges.assign(p + nn_, p + nn_ + ne_);
    return m;
}

bool MatchSet::matches(Id id, const Match& m) const {
    const std::uint32_t* p = &data_[static_cast<std::size_t>(id) * (nn_ + ne_)];
    return std::equal(m.nodes.begin(), m.nodes.end(), p) && std::equal(m.edges.begin(), m.edges.end(), p + nn_);
}

std::uint64_t MatchSet::hash(const Match& m) const {
    std::uint64_t h = 1469598103934665603ULL;
    for (auto v : m.nodes) h = (h ^ v) * 1099511628211ULL;
    for (auto v : m.edges) h = (h ^ (v + 0x9e3779b9u)) * 1099511628211ULL;
    return h;
}

bool MatchSet::add(const Match& m, const Graph& g) {
    const std::uint64_t h = hash(m);
    auto range = byHash_.equal_range(h);
    for (auto it = range.first; it != range.second; ++it)
        if (matches(it->second, m)) return false;
    Id id;
    const std::size_t width = static_cast<std::size_t>(nn_ + ne_);
    if (!free_.empty()) {
        id = free_.back();
        free_.pop_back();
    } else {
        id = static_cast<Id>(livePos_.size());
        data_.resize(data_.size() + width);
        livePos_.push_back(kNoId);
        ageSum_.push_back(0);
        agePos_.push_back(0);
    }
    std::uint32_t* p = &data_[static_cast<std::size_t>(id) * width];
    std::copy(m.nodes.begin(), m.nodes.end(), p);
    std::copy(m.edges.begin(), m.edges.end(), p + nn_);
    livePos_[id] = static_cast<std::uint32_t>(live_.size());
    live_.push_back(id);
    byHash_.emplace(h, id);
    for (NodeId n : m.nodes) {
        if (n >= byNode_.size()) byNode_.resize(std::max<std::size_t>(g.nodeCapacity(), n + 1));
        byNode_[n].push_back(id);
    }
    if (byAge_) {
        long long sum = 0;
        for (NodeId n : m.nodes) sum += g.nodeAge(n);
        for (EdgeId e : m.edges) sum += g.edgeAge(e);
        ageSum_[id] = sum;
        auto& bucket = byAgeSum_[sum];
        agePos_[id] = static_cast<std::uint32_t>(bucket.size());
        bucket.push_back(id);
    }
    return true;
}

void MatchSet::unlink(Id id) {
    // Out of the live order (swap with the last), the hash index and the age bucket.
    const std::uint32_t pos = livePos_[id];
    const Id last = live_.back();
    live_[pos] = last;
    livePos_[last] = pos;
    live_.pop_back();
    livePos_[id] = kNoId;
    const Match m = get(id);
    auto range = byHash_.equal_range(hash(m));
    for (auto it = range.first; it != range.second; ++it)
        if (it->second == id) {
            byHash_.erase(it);
            break;
        }
    if (byAge_) {
        auto b = byAgeSum_.find(ageSum_[id]);
        auto& bucket = b->second;
        const Id moved = bucket.back();
        bucket[agePos_[id]] = moved;
        agePos_[moved] = agePos_[id];
        bucket.pop_back();
        if (bucket.empty()) byAgeSum_.erase(b);
    }
    free_.push_back(id);
}

void MatchSet::removeTouching(NodeId n) {
    if (n >= byNode_.size()) return;
    std::vector<Id> ids;
    ids.swap(byNode_[n]);
    const std::size_t width = static_cast<std::size_t>(nn_ + ne_);
    for (Id id : ids) {
        if (livePos_[id] == kNoId) continue;  // stale: removed before
        const std::uint32_t* p = &data_[static_cast<std::size_t>(id) * width];
        if (std::find(p, p + nn_, n) == p + nn_) continue;  // stale: the id was reused
        unlink(id);
    }
}

void MatchSet::clear() {
    data_.clear();
    ageSum_.clear();
    livePos_.clear();
    live_.clear();
    free_.clear();
    byNode_.clear();
    byHash_.clear();
    byAgeSum_.clear();
    agePos_.clear();
}

Match MatchSet::pickRandom(Rng& rng) const {
    if (live_.size() == 1) return get(live_[0]);
    return get(live_[static_cast<std::size_t>(rng.below(live_.size()))]);
}

Match MatchSet::pickOldest(Rng& rng) const {
    const auto& bucket = byAgeSum_.begin()->second;
    if (bucket.size() == 1) return get(bucket[0]);
    return get(bucket[static_cast<std::size_t>(rng.below(bucket.size()))]);
}

}  // namespace g2d::rt
