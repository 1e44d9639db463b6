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
        if (!spare_.empty()) {
            page = std::move(spare_.back());
            spare_.pop_back();
        } else {
            page = std::make_unique<Page>();
        }
        std::fill(std::begin(page->occupied), std::end(page->occupied), 0);
        page->keys = 0;
        if (!queued_[pageNo]) {
            queued_[pageNo] = true;
            pageHeap_.push_back(pageNo);
            std::push_heap(pageHeap_.begin(), pageHeap_.end(), std::greater<>());
        }
    }
    return *page;
}

void AgeBuckets::insert(std::uint32_t id, long long key) {
    if (key < 0) throw std::logic_error("a negative age sum");
    const auto k = static_cast<std::uint64_t>(key);
    const auto pageNo = static_cast<std::size_t>(k >> kPageBits);
    // Most keys land on a page in use (keys of nearby steps are close).
    Page& page = pageNo < pages_.size() && pages_[pageNo] ? *pages_[pageNo] : pageFor(pageNo);
    const std::size_t slot = k & (kPageKeys - 1);
    std::uint64_t& word = page.occupied[slot / 64];
    const std::uint64_t bit = std::uint64_t{1} << (slot % 64);
    std::uint32_t g;
    if (word & bit) {
        g = page.groupOf[slot];
    } else {
        if (!freeGroups_.empty()) {
            g = freeGroups_.back();
            freeGroups_.pop_back();
        } else {
            g = static_cast<std::uint32_t>(groups_.size());
            groups_.emplace_back();
        }
        groups_[g].key = key;
        page.groupOf[slot] = g;
        word |= bit;
        ++page.keys;
    }
    if (id >= placeOf_.size()) placeOf_.resize(std::max<std::size_t>(id + 1, placeOf_.size() * 2));
    Group& group = groups_[g];
    placeOf_[id] = Place{g, group.size};
    if (group.spill != kNone) {
        spills_[group.spill].push_back(id);
    } else if (group.size < 2) {
        group.inl[group.size] = id;
    } else {  // a third id: move to a spill list
        if (freeSpills_.empty()) {
            freeSpills_.push_back(static_cast<std::uint32_t>(spills_.size()));
            spills_.emplace_back();
        }
        group.spill = freeSpills_.back();
        freeSpills_.pop_back();
        auto& list = spills_[group.spill];
        list.assign(group.inl, group.inl + 2);
        list.push_back(id);
    }
    ++group.size;
    ++count_;
}

void AgeBuckets::erase(std::uint32_t id) {
    const Place place = placeOf_[id];
    Group& group = groups_[place.group];
    std::uint32_t* ids = idsOf(group);
    const std::uint32_t moved = ids[group.size - 1];
    ids[place.pos] = moved;
    placeOf_[moved].pos = place.pos;
    if (group.spill != kNone) spills_[group.spill].pop_back();
    if (--group.size == 0) {
        if (group.spill != kNone) freeSpills_.push_back(group.spill);
        group.spill = kNone;
        releaseGroup(place.group);
    }
    --count_;
}

void AgeBuckets::releaseGroup(std::uint32_t group) {
    const auto k = static_cast<std::uint64_t>(groups_[group].key);
    const std::size_t pageNo = static_cast<std::size_t>(k >> kPageBits);
    Page& page = *pages_[pageNo];
    const std::size_t slot = k & (kPageKeys - 1);
    page.occupied[slot / 64] &= ~(std::uint64_t{1} << (slot % 64));
    freeGroups_.push_back(group);
    if (--page.keys == 0) spare_.push_back(std::move(pages_[pageNo]));  // its heap entry goes lazily
}

std::span<const std::uint32_t> AgeBuckets::lowest() {
    while (!pages_[pageHeap_.front()]) {
        queued_[pageHeap_.front()] = false;
        std::pop_heap(pageHeap_.begin(), pageHeap_.end(), std::greater<>());
        pageHeap_.pop_back();
    }
    const Page& page = *pages_[pageHeap_.front()];
    std::size_t w = 0;
    while (page.occupied[w] == 0) ++w;
    lowestWord_ = w;
    const std::size_t slot = w * 64 + static_cast<std::size_t>(std::countr_zero(page.occupied[w]));
    Group& group = groups_[page.groupOf[slot]];
    return {idsOf(group), group.size};
}

std::size_t AgeBuckets::peekLowest(std::uint32_t* groups, std::size_t count) const {
    if (pageHeap_.empty() || !pages_[pageHeap_.front()]) return 0;
    const Page& page = *pages_[pageHeap_.front()];
    std::size_t found = 0;
    for (std::size_t w = lowestWord_; w < kPageWords && found < count; ++w)
        for (std::uint64_t bits = page.occupied[w]; bits != 0 && found < count; bits &= bits - 1)
            groups[found++] = page.groupOf[w * 64 + static_cast<std::size_t>(std::countr_zero(bits))];
    return found;
}

void AgeBuckets::clear() { *this = AgeBuckets(); }

std::size_t AgeBuckets::memoryBytes() const {
    std::size_t bytes = pages_.capacity() * sizeof(void*) + spare_.capacity() * sizeof(void*) + pageHeap_.capacity() * 8 +
                        queued_.capacity() / 8 + groups_.capacity() * sizeof(Group) + freeGroups_.capacity() * 4 +
                        placeOf_.capacity() * sizeof(Place);
    for (const auto& p : pages_)
        if (p) bytes += sizeof(Page);
    bytes += spare_.size() * sizeof(Page);
    bytes += spills_.capacity() * sizeof(spills_[0]) + freeSpills_.capacity() * 4;
    for (const auto& list : spills_) bytes += list.capacity() * 4;
    return bytes;
}

}  // namespace g2d::rt
