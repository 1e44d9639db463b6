#pragma once
// Ids grouped by a non-negative integer key (a match's sum of creation
// steps), giving the group with the lowest key. Keys of matches made in
// nearby steps are close together, so the key space is paged: a page maps
// 1024 consecutive keys to their groups directly and marks the occupied ones
// in a bitmap; a small min-heap orders the pages in use. Insert and erase are
// O(1) (no hashing, no probing); finding the lowest key is O(1) plus
// O(log pages) when a page empties. Nothing is allocated per id once warm:
// emptied groups, their spilled id lists and pages are kept for reuse.
//
// The order of the ids inside a group depends only on the sequence of
// inserts and erases of that key (appended; an erased id's place is taken by
// the group's last), so draws over a group are reproducible.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "g2d/grow_array.hpp"
#include "g2d/prefetch.hpp"

namespace g2d::rt {

class AgeBuckets {
public:
    void insert(std::uint32_t id, long long key);
    void erase(std::uint32_t id);
    bool empty() const { return count_ == 0; }
    // The ids with the lowest key; empty() must be false.
    std::span<const std::uint32_t> lowest();
    void clear();
    std::size_t memoryBytes() const;

    // For prefetching (PickLookahead): up to `count` groups with the lowest
    // keys, lowest first, as handles for the calls below; returns how many.
    // Looks only at the lowest page, from where lowest() last found the
    // lowest key (a guess, if keys were added below it since).
    std::size_t peekLowest(std::uint32_t* groups, std::size_t count) const;
    void prefetchGroup(std::uint32_t group) const { prefetchRecordLines(&groups_[group], sizeof(Group)); }
    // Where erase() finds `id` (for an id a later step will pick).
    void prefetchPlace(std::uint32_t id) const {
        if (id < placeOf_.size()) prefetchLine(&placeOf_[id]);
    }
    std::span<const std::uint32_t> groupIds(std::uint32_t group) const {
        return {idsOf(groups_[group]), groups_[group].size};
    }

private:
    static constexpr int kPageBits = 10;
    static constexpr std::size_t kPageKeys = std::size_t{1} << kPageBits;
    static constexpr std::size_t kPageWords = kPageKeys / 64;
    struct Page {
        std::uint32_t groupOf[kPageKeys];    // valid where `occupied` is set
        std::uint64_t occupied[kPageWords];
        std::uint32_t keys = 0;              // occupied keys
    };
    // Up to two ids inline (most matches have a sum of their own, or share it
    // with one other); more spill into a pooled vector, kept for reuse.
    struct Group {
        long long key = 0;
        std::uint32_t size = 0;
        std::uint32_t spill = kNone;         // index into spills_, or kNone
        std::uint32_t inl[2] = {0, 0};
    };
    static constexpr std::uint32_t kNone = 0xffffffffu;
    std::uint32_t* idsOf(Group& g) { return g.spill == kNone ? g.inl : spills_[g.spill].data(); }
    const std::uint32_t* idsOf(const Group& g) const { return g.spill == kNone ? g.inl : spills_[g.spill].data(); }
    struct Place {
        std::uint32_t group, pos;
    };
    Page& pageFor(std::size_t pageNo);
    void releaseGroup(std::uint32_t group);

    std::vector<std::unique_ptr<Page>> pages_;   // by key >> kPageBits
    std::vector<std::unique_ptr<Page>> spare_;
    std::vector<std::uint64_t> pageHeap_;        // min-heap of page numbers (may hold emptied ones)
    std::vector<bool> queued_;                   // per page number: in pageHeap_
    GrowArray<Group> groups_;
    std::vector<std::uint32_t> freeGroups_;
    std::vector<std::vector<std::uint32_t>> spills_;
    std::vector<std::uint32_t> freeSpills_;
    GrowArray<Place> placeOf_;                   // per id: its group and its place there
    // The lowest page's first occupied word when lowest() last looked (where
    // peekLowest starts: ids leave the groups from the lowest key up).
    std::size_t lowestWord_ = 0;
    std::size_t count_ = 0;
};

}  // namespace g2d::rt
