#pragma once
// Matches: a view type, a flat buffer that searches fill, and the set of one
// rule's matches that the derivation keeps up to date between steps (see
// derivation.cpp).
//
// MatchSet stores matches flat (no allocation per match once warm), indexes
// them by node through intrusive lists (dropping every match that binds a
// node is O(those matches)), and draws
//   - random: a match uniformly from the whole set, one below(n) draw, O(1);
//   - oldest: a match uniformly among those with the lowest sum of their
//     elements' creation steps (or generations: pick.hpp), one below(k)
//     draw only when k > 1 tie, O(log distinct sums).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "g2d/age_buckets.hpp"
#include "g2d/graph.hpp"
#include "g2d/grow_array.hpp"
#include "g2d/pick.hpp"
#include "g2d/prefetch.hpp"
#include "g2d/rng.hpp"

namespace g2d::rt {

// What a pattern node's matches read of the edges at its host node beyond
// what the other pattern nodes read (see IncrementalMatches):
enum class Incidence : std::uint8_t {
    None,          // nothing: edge changes there alone leave its matches
    PatternEdges,  // the pattern's own edges: a removed one breaks a match, a new one may make one
    AllEdges,      // every edge (degrees, negative conditions): any change may make or break one
};

// One match: the host nodes bound to the pattern's nodes, the host edges
// bound to its edges and the host faces bound to its faces, in pattern
// order, stored one after the other. A view: valid while what it points
// into is unchanged.
struct Match {
    const NodeId* nodes = nullptr;
    const EdgeId* edges = nullptr;
    const FaceId* faces = nullptr;
};

// Matches as a search finds them, stored flat: a rule's node ids, edge ids, then face ids.
class MatchBuffer {
public:
    void reset(int nodes, int edges, int faces = 0) {
        nn_ = nodes;
        ne_ = edges;
        nf_ = faces;
        used_ = 0;
        count_ = 0;
    }
    void add(const NodeId* nodes, const EdgeId* edges, const FaceId* faces = nullptr) {
        // The buffer only grows (no value-initialising resize per match).
        const std::size_t width = static_cast<std::size_t>(nn_ + ne_ + nf_);
        if (used_ + width > ids_.size()) ids_.resize(std::max<std::size_t>(64, 2 * (used_ + width)));
        std::uint32_t* out = ids_.data() + used_;
        for (int i = 0; i < nn_; ++i) *out++ = nodes[i];
        for (int i = 0; i < ne_; ++i) *out++ = edges[i];
        for (int i = 0; i < nf_; ++i) *out++ = faces[i];
        used_ += width;
        ++count_;
    }
    std::size_t size() const { return count_; }
    const std::uint32_t* ids(std::size_t i) const { return ids_.data() + i * static_cast<std::size_t>(nn_ + ne_ + nf_); }
    Match operator[](std::size_t i) const { return Match{ids(i), ids(i) + nn_, ids(i) + nn_ + ne_}; }
    int nodes() const { return nn_; }
    int edges() const { return ne_; }
    int faces() const { return nf_; }

private:
    int nn_ = 0, ne_ = 0, nf_ = 0;
    std::vector<std::uint32_t> ids_;   // the first used_ entries are matches
    std::size_t used_ = 0;
    std::size_t count_ = 0;
};

// Per pattern node, what its matches read of the edges at its host
// (RuleInfo::readsIncidence; a list of another length means every edge)
// and which of the host's edge lists that is (RepairArea::kOut | kIn: none
// where it reads nothing, both where it reads every edge, else
// RuleInfo::readDirections, or both when that is not given). Match sets and
// generated repair code read these, so both repair alike.
struct IncidenceShape {
    std::vector<Incidence> reads;
    std::vector<std::uint8_t> directions;
};
IncidenceShape incidenceShape(int nodes, const std::vector<Incidence>& reads, const std::vector<std::uint8_t>& directions);

class MatchSet {
public:
    // `reads[i]`: what pattern node i reads of its host's edges; the nodes
    // that read any are indexed apart, so that matches binding a node there
    // can be dropped alone (empty: every node reads every edge).
    // `directions[i]`: which of the host's edge lists it reads
    // (RepairArea::kOut | kIn; empty: both, wherever it reads any).
    // A match binding a face binds that face's first corner too (see
    // lower::MatchFace), so the lists by node also drop matches of removed faces.
    // `pick`: a set for oldest picks keeps its matches in groups by their
    // elements' age (or generation) sum.
    MatchSet(int nodes, int edges, int faces, Pick pick, std::vector<Incidence> reads = {}, std::vector<std::uint8_t> directions = {});

    // Adds a match (nodes, edges, then faces); the caller guarantees it is not there yet.
    void add(const std::uint32_t* ids, const Graph& g);
    void add(const NodeId* nodes, const EdgeId* edges, const Graph& g) { add(nodes, edges, nullptr, g); }
    void add(const NodeId* nodes, const EdgeId* edges, const FaceId* faces, const Graph& g);
    // Removes every match that binds node `n`.
    // Inline: most nodes of a repaired area head no list of a given rule.
    void removeTouching(NodeId n) {
        const std::size_t at = 2 * std::size_t{n};
        if (at >= heads_.size()) return;
        if (heads_[at] != kNoId) unlinkAll(at);
        if (heads_[at + 1] != kNoId) unlinkAll(at + 1);
    }
    // Removes the matches that only changes to node `n`'s edge lists
    // `lists` (RepairArea::kOut | kIn) break: those binding it at a pattern
    // node reading every edge, and those binding a removed edge (found
    // through their pattern nodes that read edges). None when no pattern
    // node reads those lists.
    void removeBrokenAt(NodeId n, std::uint8_t lists, const Graph& g) {
        if ((lists & readingDirections_) != 0 && 2 * std::size_t{n} < heads_.size() && heads_[2 * std::size_t{n}] != kNoId)
            unlinkBroken(n, g);
    }
    // Asks for node `n`'s list heads ahead of a repair (IncrementalMatches::prefetch).
    void prefetchHeads(NodeId n) const {
        if (2 * std::size_t{n} < heads_.size()) prefetchLine(&heads_[2 * std::size_t{n}]);
    }
    // Whether pattern node `node` reads its host's edges (any, or all).
    bool readsIncidence(int node) const { return reads_[static_cast<std::size_t>(node)] != 0; }
    bool readsAllEdges(int node) const { return reads_[static_cast<std::size_t>(node)] == kAll; }
    // Which of its host's edge lists pattern node `node` reads (RepairArea::kOut | kIn).
    std::uint8_t readDirections(int node) const { return directions_[static_cast<std::size_t>(node)]; }
    void clear();
    // Empties the set and gives its memory back.
    void release();

    std::size_t size() const { return live_.size(); }
    bool empty() const { return live_.empty(); }
    Match at(std::size_t i) const { return view(live_[i]); }   // in the set's order
    const std::uint32_t* idsAt(std::size_t i) const { return data(live_[i]); }
    int nodes() const { return nn_; }
    int edges() const { return ne_; }
    int faces() const { return nf_; }
    long long oldestKeyAt(std::size_t i) const { return oldestKey(live_[i]); }   // its age (or generation) sum
    Match pickRandom(Rng& rng) const;
    Match pickOldest(Rng& rng);
    // For prefetching a likely later pick (PickLookahead): asks for the
    // cache line holding the set's i-th match id, or that match's record.
    void prefetchPosition(std::size_t i) const {
        if (i < live_.size()) prefetchLine(&live_[i]);
    }
    void prefetchRecordAt(std::size_t i) const {
        if (i < live_.size()) prefetchRecord(live_[i]);
    }
    // The same for oldest picks: the age groups next in line (AgeBuckets),
    // and the matches in them, by their ids.
    const AgeBuckets& ageGroups() const { return ageBuckets_; }
    void prefetchRecord(std::uint32_t id) const {
        prefetchRecordLines(data(id), std::size_t{stride_} * sizeof(std::uint32_t));
    }
    Match matchOf(std::uint32_t id) const { return view(id); }
    std::uint32_t idOf(Match m) const { return static_cast<std::uint32_t>((m.nodes - rec_.data()) / static_cast<std::ptrdiff_t>(stride_)); }
    std::size_t memoryBytes() const;

private:
    using Id = std::uint32_t;
    // One record per match id, so that dropping a match touches one place:
    //   words [0, width_)            its node ids, edge ids, then face ids
    //   word  width_                 its position in live_ (kNoId: free)
    //   words width_ + 1 + 2i, +1    next / prev in the list of matches
    //                                binding its node i (see below)
    //   3 words after (oldest only)  its place in its age group
    //                                (AgeBuckets), then its age (or
    //                                generation) sum
    // The per-node lists are doubly linked through those link words and
    // numbered by the word offset of their `next` word; each node heads one
    // list for positions that read incidences and one for the others.
    const std::uint32_t* data(Id id) const { return &rec_[static_cast<std::size_t>(id) * stride_]; }
    std::uint32_t* data(Id id) { return &rec_[static_cast<std::size_t>(id) * stride_]; }
    std::uint32_t& livePos(Id id) { return rec_[static_cast<std::size_t>(id) * stride_ + width_]; }
    std::uint32_t linkOf(Id id, int position) const {
        return static_cast<std::uint32_t>(static_cast<std::size_t>(id) * stride_ + width_ + 1 + 2 * static_cast<std::size_t>(position));
    }
    long long oldestKey(Id id) const;
    Match view(Id id) const { return Match{data(id), data(id) + nn_, data(id) + nn_ + ne_}; }
    void remove(Id id);

    int nn_, ne_, nf_;
    std::size_t width_, stride_;
    Pick pick_;
    bool byAge_;   // picksOldest(pick_)
    GrowArray<std::uint32_t> rec_;           // stride_ words per id
    GrowArray<Id> live_;
    GrowArray<Id> free_;
    static constexpr std::uint8_t kAll = static_cast<std::uint8_t>(Incidence::AllEdges);
    std::vector<std::uint8_t> reads_;        // per pattern node, an Incidence (bytes: read on every add)
    std::vector<std::uint8_t> directions_;   // per pattern node, the edge lists it reads
    std::uint8_t readingDirections_ = 0;     // their union
    // Per node two list heads side by side (one cache line for both): word
    // 2n heads the list of positions reading incidences, 2n + 1 the others'.
    GrowArray<std::uint32_t> heads_;
    std::size_t headOf(NodeId n, int position) const {
        return 2 * std::size_t{n} + (reads_[static_cast<std::size_t>(position)] != 0 ? 0 : 1);
    }
    void unlinkAll(std::size_t head);   // every match of the list heads_[head]
    void unlinkBroken(NodeId n, const Graph& g);
    AgeBuckets ageBuckets_;
};

}  // namespace g2d::rt
