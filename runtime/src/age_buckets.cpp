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
    Page& page = pageFor(static_cast<std::size_t>(k >> kPageBits));
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
    auto& ids = groups_[g].ids;
    placeOf_[id] = Place{g, static_cast<std::uint32_t>(ids.size())};
    ids.push_back(id);
    ++count_;
}

void AgeBuckets::erase(std::uint32_t id) {
    const Place place = placeOf_[id];
    auto& ids = groups_[place.group].ids;
    const std::uint32_t moved = ids.back();
    ids[place.pos] = moved;
    placeOf_[moved].pos = place.pos;
    ids.pop_back();
    --count_;
    if (ids.empty()) releaseGroup(place.group);
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

const std::vector<std::uint32_t>& AgeBuckets::lowest() {
    while (!pages_[pageHeap_.front()]) {
        queued_[pageHeap_.front()] = false;
        std::pop_heap(pageHeap_.begin(), pageHeap_.end(), std::greater<>());
        pageHeap_.pop_back();
    }
    const Page& page = *pages_[pageHeap_.front()];
    std::size_t w = 0;
    while (page.occupied[w] == 0) ++w;
    const std::size_t slot = w * 64 + static_cast<std::size_t>(std::countr_zero(page.occupied[w]));
    return groups_[page.groupOf[slot]].ids;
}

void AgeBuckets::clear() { *this = AgeBuckets(); }

std::size_t AgeBuckets::memoryBytes() const {
    std::size_t bytes = pages_.capacity() * sizeof(void*) + spare_.capacity() * sizeof(void*) + pageHeap_.capacity() * 8 +
                        queued_.capacity() / 8 + groups_.capacity() * sizeof(Group) + freeGroups_.capacity() * 4 +
                        placeOf_.capacity() * sizeof(Place);
    for (const auto& p : pages_)
        if (p) bytes += sizeof(Page);
    bytes += spare_.size() * sizeof(Page);
    for (const auto& g : groups_) bytes += g.ids.capacity() * 4;
    return bytes;
}

}  // namespace g2d::rt
