#pragma once
// Ids grouped by an integer key (a match's sum of creation steps), giving the
// group with the lowest key in O(log k) for k distinct keys, and inserting or
// erasing an id in O(1) expected plus O(log k) when a key first appears.
// Nothing is allocated per id once the groups exist: emptied groups are kept
// for reuse, and the heap of keys forgets them lazily.
#include <cstdint>
#include <vector>

namespace g2d::rt {

class AgeBuckets {
public:
    void insert(std::uint32_t id, long long key);
    void erase(std::uint32_t id, long long key);
    bool empty() const { return count_ == 0; }
    // The ids with the lowest key, in a deterministic order; empty() must be false.
    const std::vector<std::uint32_t>& lowest();
    void clear();
    std::size_t memoryBytes() const;

private:
    struct Bucket {
        long long key = 0;
        std::vector<std::uint32_t> ids;
    };
    // Open addressing from key to bucket index (linear probing, backward-shift deletion).
    std::uint32_t find(long long key) const;
    void mapInsert(long long key, std::uint32_t bucket);
    void mapErase(long long key);
    void grow();
    void compact();

    std::vector<Bucket> buckets_;
    std::vector<std::uint32_t> freeBuckets_;
    std::vector<long long> heap_;             // min-heap of keys (may hold keys of empty buckets)
    std::vector<long long> slotKey_;
    std::vector<std::uint32_t> slotBucket_;   // kEmpty when free
    std::size_t mapSize_ = 0;
    struct Place {
        std::uint32_t bucket, pos;
    };
    std::vector<Place> placeOf_;              // per id: its group and its place there
    std::size_t count_ = 0;
    std::size_t emptyBuckets_ = 0;
};

}  // namespace g2d::rt
