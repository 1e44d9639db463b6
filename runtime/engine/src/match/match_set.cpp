#include "g2d/match_set.hpp"

#include "g2d/derivation.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace g2d::rt {

MatchSet::MatchSet(int nodes, int edges, int faces, Pick pick, std::vector<Incidence> reads, std::vector<std::uint8_t> directions)
    : nn_(nodes), ne_(edges), nf_(faces), width_(static_cast<std::size_t>(nodes + edges + faces)),
      stride_(width_ + 1 + 2 * static_cast<std::size_t>(nodes) + (picksOldest(pick) ? 3 : 0)), pick_(pick), byAge_(picksOldest(pick)) {
    if (nodes < 0) throw std::logic_error("a pattern with a negative node count");
    const IncidenceShape shape = incidenceShape(nodes, reads, directions);
    for (Incidence r : shape.reads) reads_.push_back(static_cast<std::uint8_t>(r));
    directions_ = shape.directions;
    for (std::uint8_t d : directions_) readingDirections_ |= d;
}

IncidenceShape incidenceShape(int nodes, const std::vector<Incidence>& reads, const std::vector<std::uint8_t>& directions) {
    IncidenceShape out;
    const auto n = static_cast<std::size_t>(nodes);
    out.reads = reads.size() == n ? reads : std::vector<Incidence>(n, Incidence::AllEdges);
    const bool given = directions.size() == n;
    const std::uint8_t both = RepairArea::kOut | RepairArea::kIn;
    for (std::size_t i = 0; i < n; ++i) {
        const Incidence r = out.reads[i];
        out.directions.push_back(r == Incidence::None ? 0 : r == Incidence::AllEdges ? both : given ? directions[i] : both);
    }
    return out;
}

std::vector<RepairAnchor> repairAnchors(const RuleInfo& info) {
    const int nn = static_cast<int>(info.nodeKinds.size());
    const IncidenceShape shape = incidenceShape(nn, info.readsIncidence, info.readDirections);
    std::vector<RepairAnchor> out;
    for (std::size_t p = 0; p < info.nodeKinds.size(); ++p)
        out.push_back(RepairAnchor{info.nodeKinds[p], shape.directions[p], shape.reads[p] == Incidence::AllEdges,
                                   p < info.newHostAddsNothing.size() && info.newHostAddsNothing[p] != 0});
    return out;
}

long long MatchSet::oldestKey(Id id) const {
    long long sum;
    std::memcpy(&sum, data(id) + stride_ - 2, sizeof sum);
    return sum;
}

void MatchSet::add(const std::uint32_t* ids, const Graph& g) { add(ids, ids + nn_, ids + nn_ + ne_, g); }

void MatchSet::add(const NodeId* nodes, const EdgeId* edges, const FaceId* faces, const Graph& g) {
    Id id;
    if (!free_.empty()) {
        id = free_.back();
        free_.pop_back();
    } else {
        // Link numbers are 32-bit word offsets.
        if (rec_.size() + 2 * stride_ > 0xffffffffu) throw std::length_error("too many matches of one rule (over 4 G words)");
        id = static_cast<Id>(rec_.size() / stride_);
        rec_.extendUnset(stride_);   // every word is written below
    }
    std::uint32_t* p = data(id);
    for (int i = 0; i < nn_; ++i) p[i] = nodes[i];
    for (int i = 0; i < ne_; ++i) p[nn_ + i] = edges[i];
    for (int i = 0; i < nf_; ++i) p[nn_ + ne_ + i] = faces[i];
    p[width_] = static_cast<std::uint32_t>(live_.size());
    live_.push_back(id);
    std::uint32_t* links = p + width_ + 1;
    for (int i = 0; i < nn_; ++i) {
        const NodeId n = p[i];
        if (2 * std::size_t{n} >= heads_.size())
            heads_.resize(2 * (std::max<std::size_t>(g.nodeCapacity(), n + 1) + heads_.size() / 4), kNoId);
        std::uint32_t& head = heads_[headOf(n, i)];
        const std::uint32_t link = linkOf(id, i);
        links[2 * i] = head;
        links[2 * i + 1] = kNoId;
        if (head != kNoId) rec_[head + 1] = link;
        head = link;
    }
    if (byAge_) {
        long long sum = 0;
        if (pick_ == Pick::OldestGeneration) {
            for (int i = 0; i < nn_; ++i) sum += g.nodeGeneration(p[i]);
            for (int i = 0; i < ne_; ++i) sum += g.edgeGeneration(p[nn_ + i]);
            for (int i = 0; i < nf_; ++i) sum += g.faceGeneration(p[nn_ + ne_ + i]);
        } else {
            for (int i = 0; i < nn_; ++i) sum += g.nodeAge(p[i]);
            for (int i = 0; i < ne_; ++i) sum += g.edgeAge(p[nn_ + i]);
            for (int i = 0; i < nf_; ++i) sum += g.faceAge(p[nn_ + ne_ + i]);
        }
        std::memcpy(p + stride_ - 2, &sum, sizeof sum);
        p[stride_ - 3] = ageBuckets_.insert(id, sum);
    }
}

void MatchSet::remove(Id id) {
    std::uint32_t* p = data(id);
    const std::uint32_t* links = p + width_ + 1;
    for (int i = 0; i < nn_; ++i) {
        const std::uint32_t next = links[2 * i], prev = links[2 * i + 1];
        if (prev != kNoId)
            rec_[prev] = next;
        else
            heads_[headOf(p[i], i)] = next;
        if (next != kNoId) rec_[next + 1] = prev;
    }
    // Out of the live order: swap with the last.
    const std::uint32_t pos = p[width_];
    const Id last = live_.back();
    live_[pos] = last;
    livePos(last) = pos;
    live_.pop_back();
    p[width_] = kNoId;
    if (byAge_) {
        const std::uint32_t place = p[stride_ - 3];
        const std::uint32_t moved = ageBuckets_.erase(static_cast<std::uint64_t>(oldestKey(id)), place);
        if (moved != AgeBuckets::kNoMove) data(moved)[stride_ - 3] = place;
    }
    free_.push_back(id);
}

void MatchSet::unlinkAll(std::size_t head) {
    while (heads_[head] != kNoId) remove(static_cast<Id>(heads_[head] / stride_));
}

void MatchSet::unlinkBroken(NodeId n, const Graph& g) {
    std::uint32_t link = heads_[2 * std::size_t{n}];
    while (link != kNoId) {
        // Read before a removal unlinks it. A match binds a host node once,
        // except where `dpo` wildcards share one: its links to that node were
        // added one after the other, so they are neighbours here, skipped with it.
        std::uint32_t next = rec_[link];
        const Id id = static_cast<Id>(link / stride_);
        const int position = static_cast<int>((link - id * stride_ - width_ - 1) / 2);
        bool broken = reads_[static_cast<std::size_t>(position)] == kAll;
        const std::uint32_t* edges = data(id) + nn_;
        for (int i = 0; i < ne_ && !broken; ++i) broken = !g.edgeAlive(edges[i]);
        if (broken) {
            while (next != kNoId && next / stride_ == id) next = rec_[next];
            remove(id);
        }
        link = next;
    }
}

void MatchSet::clear() {
    rec_.clear();
    live_.clear();
    free_.clear();
    heads_.clear();
    ageBuckets_.clear();
}

void MatchSet::release() {
    for (auto* a : {&rec_, &live_, &free_, &heads_}) *a = GrowArray<std::uint32_t>{};
    ageBuckets_ = AgeBuckets();
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
    return (rec_.capacity() + live_.capacity() + free_.capacity() + heads_.capacity()) * 4 +
           ageBuckets_.memoryBytes();
}

}  // namespace g2d::rt
