#include "g2d/age_buckets.hpp"

#include <algorithm>
#include <bit>
#include <functional>
#include <stdexcept>

namespace g2d::rt {

AgeBuckets::Page& AgeBuckets::pageFor(std::size_t pageNo) {
    if (pageNo >= pages_.size()) {
        const std::size_t size = std::max(pageNo + 1, pages_.size() * 2);
        pages_.resize(size);
        queued_.resize(size, false);
    }
    auto& page = pages_[pageNo];
    if (!page) {
        if (!spare_.empty()) {   // emptied: every bit is 0 again
            page = std::move(spare_.back());
            spare_.pop_back();
        } else {
            // Slots are written when their key arrives: not clearing 16 KiB
            // leaves a small run's untouched slots unfaulted.
            page.reset(new Page);
            std::fill(std::begin(page->occupied), std::end(page->occupied), 0);
        }
        page->keys = 0;
        page->lowWord = kPageWords;
        if (!queued_[pageNo]) {
            queued_[pageNo] = true;
            pageHeap_.push_back(pageNo);
            std::push_heap(pageHeap_.begin(), pageHeap_.end(), std::greater<>());
        }
    }
    return *page;
}

std::uint32_t AgeBuckets::insert(std::uint32_t id, long long key) {
    if (key < 0) throw std::logic_error("a negative age sum");
    const auto k = static_cast<std::uint64_t>(key);
    const auto pageNo = static_cast<std::size_t>(k >> kPageBits);
    // Most keys land on a page in use (keys of nearby steps are close).
    Page& page = pageNo < pages_.size() && pages_[pageNo] ? *pages_[pageNo] : pageFor(pageNo);
    const std::size_t at = k & (kPageKeys - 1);
    Slot& slot = page.slots[at];
    std::uint64_t& word = page.occupied[at / 64];
    const std::uint64_t bit = std::uint64_t{1} << (at % 64);
    if ((word & bit) == 0) {   // a new key: its slot holds nothing yet
        word |= bit;
        page.lowWord = std::min(page.lowWord, static_cast<std::uint32_t>(at / 64));
        ++page.keys;
        slot.size = 0;
    }
    const std::uint32_t size = slot.size & kSizeMask;
    if (slot.size & kSpilled) {
        spills_[slot.ids[0]].push_back(id);
        ++slot.size;
    } else if (size < kInline) {
        slot.ids[size] = id;
        ++slot.size;
    } else {
        spill(slot, id);
    }
    ++count_;
    return size;
}

// A fourth id: the group's ids move to a pooled list, in their order.
void AgeBuckets::spill(Slot& slot, std::uint32_t id) {
    if (freeSpills_.empty()) {
        freeSpills_.push_back(static_cast<std::uint32_t>(spills_.size()));
        spills_.emplace_back();
    }
    const std::uint32_t list = freeSpills_.back();
    freeSpills_.pop_back();
    auto& ids = spills_[list];
    ids.assign(slot.ids, slot.ids + kInline);
    ids.push_back(id);
    slot.ids[0] = list;
    slot.size = (kInline + 1) | kSpilled;
}

std::uint32_t AgeBuckets::erase(std::uint64_t key, std::uint32_t place) {
    Slot& slot = slotOf(key);
    std::uint32_t* ids = idsOf(slot);
    const std::uint32_t last = (slot.size & kSizeMask) - 1;
    const std::uint32_t moved = place == last ? kNoMove : ids[last];
    ids[place] = ids[last];
    if (slot.size & kSpilled) {
        spills_[slot.ids[0]].pop_back();
        if (last == 0) freeSpills_.push_back(slot.ids[0]);
    }
    --slot.size;
    if (last == 0) release(key);
    --count_;
    return moved;
}

void AgeBuckets::release(std::uint64_t key) {
    const std::size_t pageNo = static_cast<std::size_t>(key >> kPageBits);
    Page& page = *pages_[pageNo];
    const std::size_t at = key & (kPageKeys - 1);
    page.occupied[at / 64] &= ~(std::uint64_t{1} << (at % 64));
    if (--page.keys == 0) spare_.push_back(std::move(pages_[pageNo]));  // its heap entry goes lazily
}

std::span<const std::uint32_t> AgeBuckets::lowest() {
    while (!pages_[pageHeap_.front()]) {
        queued_[pageHeap_.front()] = false;
        std::pop_heap(pageHeap_.begin(), pageHeap_.end(), std::greater<>());
        pageHeap_.pop_back();
    }
    Page& page = *pages_[pageHeap_.front()];
    std::uint32_t w = page.lowWord;
    while (page.occupied[w] == 0) ++w;
    page.lowWord = w;
    const Slot& slot = page.slots[w * 64 + static_cast<std::size_t>(std::countr_zero(page.occupied[w]))];
    return {idsOf(slot), slot.size & kSizeMask};
}

std::size_t AgeBuckets::peekLowest(std::uint64_t* keys, std::size_t count) const {
    if (pageHeap_.empty() || !pages_[pageHeap_.front()]) return 0;
    const std::uint64_t pageNo = pageHeap_.front();
    const Page& page = *pages_[pageNo];
    std::size_t found = 0;
    for (std::size_t w = page.lowWord; w < kPageWords && found < count; ++w)
        for (std::uint64_t bits = page.occupied[w]; bits != 0 && found < count; bits &= bits - 1)
            keys[found++] = (pageNo << kPageBits) + w * 64 + static_cast<std::uint64_t>(std::countr_zero(bits));
    return found;
}

void AgeBuckets::clear() { *this = AgeBuckets(); }

std::size_t AgeBuckets::memoryBytes() const {
    std::size_t bytes = pages_.capacity() * sizeof(void*) + spare_.capacity() * sizeof(void*) + pageHeap_.capacity() * 8 +
                        queued_.capacity() / 8;
    for (const auto& p : pages_)
        if (p) bytes += sizeof(Page);
    bytes += spare_.size() * sizeof(Page);
    bytes += spills_.capacity() * sizeof(spills_[0]) + freeSpills_.capacity() * 4;
    for (const auto& list : spills_) bytes += list.capacity() * 4;
    return bytes;
}

}  // namespace g2d::rt
