#include "g2d/grow_array.hpp"

#include <cstdint>
#include <cstdlib>
#include <sys/mman.h>
#include <unistd.h>

namespace g2d::rt::grow_detail {

namespace {

// Blocks this large are placed on 2 MiB boundaries and asked to be backed by
// huge pages: a derivation of millions of elements then takes 512 times
// fewer page faults while its arrays fill, and its scattered reads miss the
// TLB far less often (a cost that otherwise grows with the graph).
constexpr std::size_t kHugePage = std::size_t{2} << 20;

std::size_t pageRounded(std::size_t bytes) {
    static const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    return (bytes + page - 1) / page * page;
}

bool mapped(std::size_t bytes) { return bytes >= kMappedBytes; }

// Reserves `bytes` of address space at a 2 MiB boundary when that large
// (the unaligned ends of a larger reservation are given back).
void* reserve(std::size_t bytes) {
    const bool huge = bytes >= kHugePage;
    const std::size_t span = huge ? bytes + kHugePage : bytes;
    void* p = mmap(nullptr, span, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    if (!huge) return p;
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t aligned = (at + kHugePage - 1) & ~(kHugePage - 1);
    if (aligned > at) munmap(p, aligned - at);
    const std::uintptr_t end = at + span, used = aligned + bytes;
    if (end > used) munmap(reinterpret_cast<void*>(used), end - used);
    return reinterpret_cast<void*>(aligned);
}

void adviseHuge(void* p, std::size_t bytes) {
    // Advice only: where the kernel has no huge pages, small ones serve.
    if (bytes >= kHugePage) madvise(p, bytes, MADV_HUGEPAGE);
}

}  // namespace

void* resize(void* block, std::size_t oldBytes, std::size_t newBytes, std::size_t usedBytes) {
    if (!mapped(newBytes)) {
        // Small: malloc's realloc (the old block is small too: arrays only grow).
        void* p = std::realloc(block, newBytes);
        if (!p) throw std::bad_alloc();
        return p;
    }
    const std::size_t bytes = pageRounded(newBytes);
    if (block && mapped(oldBytes)) {
        // The kernel moves the pages; nothing is copied. Into an aligned
        // reservation when the block is large enough for huge pages.
        void* p;
        if (bytes >= kHugePage) {
            void* to = reserve(bytes);
            p = mremap(block, pageRounded(oldBytes), bytes, MREMAP_MAYMOVE | MREMAP_FIXED, to);
            if (p == MAP_FAILED) munmap(to, bytes);
        } else {
            p = mremap(block, pageRounded(oldBytes), bytes, MREMAP_MAYMOVE);
        }
        if (p == MAP_FAILED) throw std::bad_alloc();
        adviseHuge(p, bytes);
        return p;
    }
    void* p = reserve(bytes);
    adviseHuge(p, bytes);
    if (block) {
        std::memcpy(p, block, usedBytes);
        std::free(block);
    }
    return p;
}

void release(void* block, std::size_t bytes) noexcept {
    if (!block) return;
    if (mapped(bytes))
        munmap(block, pageRounded(bytes));
    else
        std::free(block);
}

}  // namespace g2d::rt::grow_detail
