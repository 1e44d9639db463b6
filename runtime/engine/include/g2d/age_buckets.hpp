#pragma once
// Ids grouped by a non-negative integer key (a match's sum of creation
// steps), giving the group with the lowest key. Keys of matches made in
// nearby steps are close together, so the key space is paged: a page holds
// the groups of 1024 consecutive keys in place (a 16-byte slot per key, with
// up to three ids inline) and marks the occupied ones in a bitmap; a small
// min-heap orders the pages in use. Insert and erase are O(1) (no hashing,
// no probing) and read one slot; finding the lowest key is O(1) plus
// O(log pages) when a page empties. Nothing is allocated per id once warm:
// spilled id lists and emptied pages are kept for reuse.
//
// The order of the ids inside a group depends only on the sequence of
// inserts and erases of that key (appended; an erased id's place is taken by
// the group's last), so draws over a group are reproducible.
//
// The caller keeps each id's key and place in its group (MatchSet keeps
// them in the match's record, which its removal reads anyway): an array of
// places per id here was 16 bytes a match more and one more cache line to
// each insert and erase.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "g2d/prefetch.hpp"

namespace g2d::rt {

class AgeBuckets {
public:
    // Adds `id` to the group of `key`; returns its place there.
    std::uint32_t insert(std::uint32_t id, long long key);
    // Takes the id at place `place` out of the group of `key`; the group's
    // last id moves to that place: returns that id, or kNoMove when the
    // erased id was the last.
    static constexpr std::uint32_t kNoMove = 0xffffffffu;
    std::uint32_t erase(std::uint64_t key, std::uint32_t place);
    bool empty() const { return count_ == 0; }
    // The ids with the lowest key; empty() must be false.
    std::span<const std::uint32_t> lowest();
    void clear();
    std::size_t memoryBytes() const;

    // For prefetching (PickLookahead): up to `count` occupied keys, lowest
    // first, as handles for the calls below; returns how many. Looks only at
    // the lowest page (none if it has just emptied).
    std::size_t peekLowest(std::uint64_t* keys, std::size_t count) const;
    void prefetchGroup(std::uint64_t key) const { prefetchLine(&slotOf(key)); }
    std::span<const std::uint32_t> groupIds(std::uint64_t key) const {
        const Slot& slot = slotOf(key);
        return {idsOf(slot), slot.size & kSizeMask};
    }

private:
    static constexpr int kPageBits = 10;
    static constexpr std::size_t kPageKeys = std::size_t{1} << kPageBits;
    static constexpr std::size_t kPageWords = kPageKeys / 64;
    // A key's group, in its page: 16 bytes, four to a cache line. Most
    // matches have a sum of their own or share it with one or two others
    // (Koch level 10: 94 % of inserts find at most two ids there); a fourth
    // id moves the group to a pooled list (ids[0] then names it) until the
    // group empties. Only slots whose bit is set in `occupied` hold a group.
    struct alignas(16) Slot {
        std::uint32_t size;                  // ids, plus kSpilled once spilled
        std::uint32_t ids[3];
    };
    static constexpr std::uint32_t kSpilled = 0x80000000u;
    static constexpr std::uint32_t kSizeMask = ~kSpilled;
    static constexpr std::uint32_t kInline = 3;
    struct Page {
        Slot slots[kPageKeys];
        std::uint64_t occupied[kPageWords];  // the keys with a group
        std::uint32_t keys;                  // occupied keys
        std::uint32_t lowWord;               // no occupied word lies below it
    };
    std::uint32_t* idsOf(Slot& s) { return s.size & kSpilled ? spills_[s.ids[0]].data() : s.ids; }
    const std::uint32_t* idsOf(const Slot& s) const { return s.size & kSpilled ? spills_[s.ids[0]].data() : s.ids; }
    Slot& slotOf(std::uint64_t key) { return pages_[key >> kPageBits]->slots[key & (kPageKeys - 1)]; }
    const Slot& slotOf(std::uint64_t key) const { return pages_[key >> kPageBits]->slots[key & (kPageKeys - 1)]; }
    Page& pageFor(std::size_t pageNo);
    void spill(Slot& slot, std::uint32_t id);
    void release(std::uint64_t key);

    std::vector<std::unique_ptr<Page>> pages_;   // by key >> kPageBits
    std::vector<std::unique_ptr<Page>> spare_;   // emptied pages: every bit 0
    std::vector<std::uint64_t> pageHeap_;        // min-heap of page numbers (may hold emptied ones)
    std::vector<bool> queued_;                   // per page number: in pageHeap_
    std::vector<std::vector<std::uint32_t>> spills_;
    std::vector<std::uint32_t> freeSpills_;
    std::size_t count_ = 0;
};

}  // namespace g2d::rt
