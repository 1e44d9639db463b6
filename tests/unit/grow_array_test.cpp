// GrowArray: contents survive growth from a malloc'd block into a memory
// mapping and across mremap-ed growth of the mapping; a mapped array's next
// chunk is faulted in ahead; copies are deep; resize, append, assign and
// pop_back behave as std::vector's.
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <sys/mman.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "g2d/grow_array.hpp"

using g2d::rt::GrowArray;

namespace {
struct Rec {
    std::uint64_t a;
    std::uint32_t b;
};
}  // namespace

TEST_CASE("GrowArray keeps its elements while growing past the mapped size", "[grow_array]") {
    GrowArray<Rec> arr;
    std::vector<Rec> model;
    // 3 M records of 16 bytes: 48 MB, many mremap growths after the switch to a mapping.
    for (std::uint32_t i = 0; i < 3'000'000; ++i) {
        const Rec r{i * 2654435761ull, i ^ 0x5a5a5a5au};
        arr.push_back(r);
        model.push_back(r);
        if ((i & (i + 1)) == 0) {   // at every power of two minus one: compare all
            REQUIRE(arr.size() == model.size());
            std::size_t differ = 0;
            for (std::size_t k = 0; k < model.size(); ++k) differ += arr[k].a != model[k].a || arr[k].b != model[k].b;
            REQUIRE(differ == 0);
        }
    }
    REQUIRE(arr.capacity() >= arr.size());
    REQUIRE(arr.back().b == model.back().b);
    std::size_t mismatches = 0;
    for (std::size_t k = 0; k < model.size(); ++k) mismatches += arr[k].a != model[k].a || arr[k].b != model[k].b;
    REQUIRE(mismatches == 0);
}

namespace {
// Whether the mapping holding `p` is advised to use huge pages (its
// VmFlags in /proc/self/smaps include "hg").
bool hugePageAdvised(const void* p) {
    std::ifstream smaps("/proc/self/smaps");
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    bool inside = false;
    for (std::string line; std::getline(smaps, line);) {
        unsigned long long from = 0, to = 0;
        if (std::sscanf(line.c_str(), "%llx-%llx ", &from, &to) == 2 && line.find(' ') > line.find('-')) {
            inside = from <= at && at < to;
        } else if (inside && line.rfind("VmFlags:", 0) == 0) {
            return line.find(" hg") != std::string::npos;
        }
    }
    return false;
}
}  // namespace

TEST_CASE("GrowArray asks for huge pages for arrays of 2 MiB or more", "[grow_array]") {
    if (g2d::rt::grow_detail::kMappedBytes == ~std::size_t{0}) return;   // sanitizer builds: all from malloc
    // 56-byte records: their capacities never fill the first reservation
    // (kReservedBytes) exactly, so the mapping is advised while part of it
    // is unused and then moved, as the graph's records are.
    struct Wide {
        std::uint64_t word[7];
    };
    GrowArray<Wide> arr;
    std::size_t advised = 0, large = 0;
    const std::size_t count = 2 * g2d::rt::grow_detail::kReservedBytes / sizeof(Wide);
    for (std::uint64_t i = 0; i < count; ++i) {
        const auto before = arr.capacity();
        arr.push_back(Wide{{i, 0, 0, 0, 0, 0, i}});
        if (arr.capacity() != before && arr.size() * sizeof(Wide) >= (std::size_t{2} << 20)) {
            ++large;   // it grew: checked after each growth
            advised += hugePageAdvised(arr.data());
            REQUIRE(reinterpret_cast<std::uintptr_t>(arr.data()) % (std::size_t{2} << 20) == 0);
            REQUIRE(arr[i / 2].word[6] == i / 2);
        }
    }
    REQUIRE(large >= 4);
    REQUIRE(advised == large);
    REQUIRE(arr.size() * sizeof(Wide) > g2d::rt::grow_detail::kReservedBytes);
    REQUIRE(arr[count - 1].word[0] == count - 1);
}

TEST_CASE("GrowArray copies are deep and moves leave the source empty", "[grow_array]") {
    GrowArray<std::uint32_t> big;
    for (std::uint32_t i = 0; i < 200'000; ++i) big.push_back(i);   // 800 KB: mapped
    GrowArray<std::uint32_t> copy = big;
    copy[7] = 99;
    REQUIRE(big[7] == 7);
    REQUIRE(copy.size() == 200'000);
    REQUIRE(copy[199'999] == 199'999);
    GrowArray<std::uint32_t> moved = std::move(copy);
    REQUIRE(copy.empty());
    REQUIRE(moved[7] == 99);
    GrowArray<std::uint32_t> small;
    small.push_back(1);
    small = big;                      // small (malloc'd) replaced by a mapped copy
    REQUIRE(small.size() == big.size());
    REQUIRE(small[123'456] == 123'456);
    big = GrowArray<std::uint32_t>{};  // mapped replaced by empty
    REQUIRE(big.empty());
}

TEST_CASE("GrowArray resize, append, assign, pop_back, extendUnset and self push_back", "[grow_array]") {
    GrowArray<int> arr;
    arr.resize(5, 3);
    REQUIRE(std::vector<int>(arr.begin(), arr.end()) == std::vector<int>{3, 3, 3, 3, 3});
    const int more[] = {1, 2};
    arr.append(more, more + 2);
    arr.pop_back();
    REQUIRE(std::vector<int>(arr.begin(), arr.end()) == std::vector<int>{3, 3, 3, 3, 3, 1});
    arr.resize(2);
    REQUIRE(arr.size() == 2);
    arr.resize(4);                    // new elements are value-initialised
    REQUIRE(arr[3] == 0);
    arr.assign(3, 8);
    REQUIRE(std::vector<int>(arr.begin(), arr.end()) == std::vector<int>{8, 8, 8});
    // Pushing or emplacing an element of the array itself while it grows.
    GrowArray<int> self;
    self.push_back(42);
    for (int i = 0; i < 100'000; ++i) self.push_back(self[0]);
    REQUIRE(self.size() == 100'001);
    REQUIRE(self[100'000] == 42);
    GrowArray<Rec> recs;
    recs.push_back(Rec{7, 9});
    for (int i = 0; i < 100'000; ++i) recs.emplace_back(recs[0]);
    REQUIRE(recs.size() == 100'001);
    REQUIRE(recs[100'000].a == 7);
    REQUIRE(recs[100'000].b == 9);
    // extendUnset appends room that the caller writes; earlier elements stay.
    int* room = arr.extendUnset(3);
    REQUIRE(room == arr.data() + 3);
    room[0] = 4, room[1] = 5, room[2] = 6;
    REQUIRE(std::vector<int>(arr.begin(), arr.end()) == std::vector<int>{8, 8, 8, 4, 5, 6});
    for (int i = 0; i < 10'000; ++i) *arr.extendUnset(1) = i;   // across growths
    REQUIRE(arr.size() == 10'006);
    REQUIRE(arr[5] == 6);
    REQUIRE(arr[10'005] == 9'999);
    arr.clear();
    REQUIRE(arr.empty());
}

namespace {
// Whether this kernel can fault pages in without writing them (Linux 5.14
// on): without it GrowArray leaves the faults to the writes.
bool populateSupported() {
    const std::size_t bytes = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) return false;
    const bool ok = madvise(p, bytes, MADV_POPULATE_WRITE) == 0;
    munmap(p, bytes);
    return ok;
}

// Whether the page holding `p` is resident (mincore).
bool resident(const void* p) {
    const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    const auto at = reinterpret_cast<std::uintptr_t>(p) & ~(page - 1);
    unsigned char in = 0;
    return mincore(reinterpret_cast<void*>(at), page, &in) == 0 && (in & 1) != 0;
}
}  // namespace

TEST_CASE("A mapped GrowArray takes its room a chunk at a time and has the next chunk faulted in ahead",
          "[grow_array]") {
    if (g2d::rt::grow_detail::kMappedBytes == ~std::size_t{0}) return;   // sanitizer builds: all from malloc
    const std::size_t chunk = g2d::rt::grow_detail::kChunkBytes;
    GrowArray<Rec> arr;
    // Past two chunks: the array is a chunk long, so the chunk after its
    // room is asked for.
    while (arr.size() * sizeof(Rec) < 2 * chunk + 100) arr.push_back(Rec{arr.size(), 7});
    const std::size_t room = arr.capacity() * sizeof(Rec);
    REQUIRE(room >= arr.size() * sizeof(Rec));
    REQUIRE(room - arr.size() * sizeof(Rec) < chunk);   // a chunk at a time, not doubling
    const char* next = reinterpret_cast<const char*>(arr.data()) + room;
    // Not written by anyone: resident only if the helper thread faulted it in.
    if (populateSupported()) {
        bool ahead = false;
        for (int wait = 0; wait < 200 && !ahead; ++wait) {
            ahead = resident(next) && resident(next + chunk - 1);
            if (!ahead) std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        REQUIRE(ahead);
    } else {
        WARN("this kernel has no MADV_POPULATE_WRITE: nothing is faulted in ahead");
    }
    // Faulting in never changes what is there.
    std::size_t wrong = 0;
    for (std::size_t k = 0; k < arr.size(); ++k) wrong += arr[k].a != k || arr[k].b != 7;
    REQUIRE(wrong == 0);
    // A medium array (mapped, under a chunk) keeps small pages, and its
    // room past what it wrote is not touched.
    GrowArray<Rec> medium;
    while (medium.size() * sizeof(Rec) < 200 << 10) medium.push_back(Rec{1, 2});
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    REQUIRE_FALSE(hugePageAdvised(medium.data()));
    REQUIRE_FALSE(resident(reinterpret_cast<const char*>(medium.data()) + (1 << 20)));
}
