#include "g2d/age_buckets.hpp"

#include <algorithm>
#include <functional>

namespace g2d::rt {

namespace {
constexpr std::uint32_t kEmpty = 0xffffffffu;

// Keys close together (matches made in nearby steps) land in nearby slots,
// runs of 64 keys are scattered over the table.
std::size_t hashKey(long long key, std::size_t mask) {
    const auto k = static_cast<std::uint64_t>(key);
    std::uint64_t x = (k >> 6) * 0x9e3779b97f4a7c15ULL;
    return static_cast<std::size_t>(((x ^ (x >> 29)) << 6) | (k & 63)) & mask;
}
}  // namespace

std::uint32_t AgeBuckets::find(long long key) const {
    if (slotBucket_.empty()) return kEmpty;
    const std::size_t mask = slotBucket_.size() - 1;
    for (std::size_t i = hashKey(key, mask);; i = (i + 1) & mask) {
        if (slotBucket_[i] == kEmpty) return kEmpty;
        if (slotKey_[i] == key) return slotBucket_[i];
    }
}

void AgeBuckets::grow() {
    std::vector<long long> keys;
    std::vector<std::uint32_t> values;
    keys.swap(slotKey_);
    values.swap(slotBucket_);
    const std::size_t size = std::max<std::size_t>(16, keys.size() * 2);
    slotKey_.assign(size, 0);
    slotBucket_.assign(size, kEmpty);
    mapSize_ = 0;
    for (std::size_t i = 0; i < keys.size(); ++i)
        if (values[i] != kEmpty) mapInsert(keys[i], values[i]);
}

void AgeBuckets::mapInsert(long long key, std::uint32_t bucket) {
    if ((mapSize_ + 1) * 2 > slotBucket_.size()) grow();
    const std::size_t mask = slotBucket_.size() - 1;
    std::size_t i = hashKey(key, mask);
    while (slotBucket_[i] != kEmpty) i = (i + 1) & mask;
    slotKey_[i] = key;
    slotBucket_[i] = bucket;
    ++mapSize_;
}

void AgeBuckets::mapErase(long long key) {
    const std::size_t mask = slotBucket_.size() - 1;
    std::size_t i = hashKey(key, mask);
    while (slotKey_[i] != key || slotBucket_[i] == kEmpty) i = (i + 1) & mask;
    // Backward shift: move later entries of the probe run into the hole.
    for (std::size_t j = (i + 1) & mask; slotBucket_[j] != kEmpty; j = (j + 1) & mask) {
        const std::size_t home = hashKey(slotKey_[j], mask);
        const bool movable = i <= j ? (home <= i || home > j) : (home <= i && home > j);
        if (movable) {
            slotKey_[i] = slotKey_[j];
            slotBucket_[i] = slotBucket_[j];
            i = j;
        }
    }
    slotBucket_[i] = kEmpty;
    --mapSize_;
}

void AgeBuckets::insert(std::uint32_t id, long long key) {
    std::uint32_t b = find(key);
    if (b == kEmpty) {
        if (!freeBuckets_.empty()) {
            b = freeBuckets_.back();
            freeBuckets_.pop_back();
        } else {
            b = static_cast<std::uint32_t>(buckets_.size());
            buckets_.emplace_back();
        }
        buckets_[b].key = key;
        mapInsert(key, b);
        heap_.push_back(key);
        std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
    } else if (buckets_[b].ids.empty()) {
        --emptyBuckets_;
    }
    if (id >= placeOf_.size()) placeOf_.resize(std::max<std::size_t>(id + 1, placeOf_.size() * 2));
    placeOf_[id] = Place{b, static_cast<std::uint32_t>(buckets_[b].ids.size())};
    buckets_[b].ids.push_back(id);
    ++count_;
}

void AgeBuckets::erase(std::uint32_t id, long long key) {
    (void)key;
    auto& ids = buckets_[placeOf_[id].bucket].ids;
    const std::uint32_t pos = placeOf_[id].pos;
    const std::uint32_t moved = ids.back();
    ids[pos] = moved;
    placeOf_[moved].pos = pos;
    ids.pop_back();
    --count_;
    if (ids.empty() && ++emptyBuckets_ > 1024 && emptyBuckets_ > 2 * (buckets_.size() - freeBuckets_.size() - emptyBuckets_))
        compact();
}

void AgeBuckets::compact() {
    // Too many emptied groups wait in the heap: forget them all at once.
    heap_.clear();
    for (std::uint32_t b = 0; b < buckets_.size(); ++b) {
        if (find(buckets_[b].key) != b) continue;  // already free
        if (buckets_[b].ids.empty()) {
            mapErase(buckets_[b].key);
            freeBuckets_.push_back(b);
        } else {
            heap_.push_back(buckets_[b].key);
        }
    }
    std::make_heap(heap_.begin(), heap_.end(), std::greater<>());
    emptyBuckets_ = 0;
}

const std::vector<std::uint32_t>& AgeBuckets::lowest() {
    while (true) {
        const std::uint32_t b = find(heap_.front());
        if (!buckets_[b].ids.empty()) return buckets_[b].ids;
        std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
        heap_.pop_back();
        mapErase(buckets_[b].key);
        freeBuckets_.push_back(b);
        --emptyBuckets_;
    }
}

void AgeBuckets::clear() { *this = AgeBuckets(); }

std::size_t AgeBuckets::memoryBytes() const {
    std::size_t bytes = buckets_.capacity() * sizeof(Bucket) + heap_.capacity() * sizeof(long long) +
                        slotKey_.capacity() * sizeof(long long) + slotBucket_.capacity() * 4 +
                        placeOf_.capacity() * sizeof(Place) + freeBuckets_.capacity() * 4;
    for (const auto& b : buckets_) bytes += b.ids.capacity() * 4;
    return bytes;
}

}  // namespace g2d::rt
