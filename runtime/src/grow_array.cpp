#include "g2d/grow_array.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <sys/mman.h>
#include <unistd.h>

namespace g2d::rt::grow_detail {

namespace {

// Mappings are placed on 2 MiB boundaries, and one is asked to be backed by
// huge pages once the array in it is that large: a derivation of millions
// of elements then takes 512 times fewer page faults while its arrays fill,
// and its scattered reads miss the TLB far less often (a cost that
// otherwise grows with the graph).
constexpr std::size_t kHugePage = std::size_t{2} << 20;

std::size_t pageRounded(std::size_t bytes) {
    static const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    return (bytes + page - 1) / page * page;
}

bool mapped(std::size_t bytes) { return bytes >= kMappedBytes; }

// `bytes` of address space at a 2 MiB boundary, or nullptr. Reserved only:
// a page takes memory when first written.
void* reserve(std::size_t bytes) {
    const std::size_t span = bytes + kHugePage;
    void* p = mmap(nullptr, span, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED) return nullptr;
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t aligned = (at + kHugePage - 1) & ~(kHugePage - 1);
    if (aligned > at) munmap(p, aligned - at);
    const std::uintptr_t end = at + span, used = aligned + bytes;
    if (end > used) munmap(reinterpret_cast<void*>(used), end - used);
    return reinterpret_cast<void*>(aligned);
}

// A reservation of at least `bytes`: kReservedBytes ahead when the system
// grants that much address space, else just what is needed.
void* reserveAhead(std::size_t& bytes) {
    const std::size_t wanted = pageRounded(std::max(bytes, kReservedBytes));
    if (void* p = reserve(wanted)) {
        bytes = wanted;
        return p;
    }
    bytes = pageRounded(bytes);
    if (void* p = reserve(bytes)) return p;
    throw std::bad_alloc();
}

}  // namespace

void* grow(void* block, std::size_t& roomBytes, std::size_t newBytes, std::size_t usedBytes) {
    if (!mapped(newBytes)) {
        // Small: malloc's realloc (the old block is small too: arrays only grow).
        void* p = std::realloc(block, newBytes);
        if (!p) throw std::bad_alloc();
        roomBytes = newBytes;
        return p;
    }
    if (block && mapped(roomBytes)) {
        // Past its reservation: the kernel moves the pages into a new one
        // (twice as large); nothing is copied.
        std::size_t bytes = std::max(newBytes, 2 * roomBytes);
        void* to = reserveAhead(bytes);
        void* p = mremap(block, roomBytes, bytes, MREMAP_MAYMOVE | MREMAP_FIXED, to);
        if (p == MAP_FAILED) {
            munmap(to, bytes);
            throw std::bad_alloc();
        }
        roomBytes = bytes;
        return p;
    }
    std::size_t bytes = newBytes;
    void* p = reserveAhead(bytes);
    if (block) {
        std::memcpy(p, block, usedBytes);
        std::free(block);
    }
    roomBytes = bytes;
    return p;
}

void adviseHuge(void* block, std::size_t roomBytes, std::size_t bytes) noexcept {
    // Advice only: where the kernel has no huge pages, small ones serve. The
    // whole mapping, so that it stays one region (mremap moves only one),
    // and a mapping moved by mremap keeps it.
    if (block && mapped(roomBytes) && bytes >= kHugePage) madvise(block, roomBytes, MADV_HUGEPAGE);
}

void release(void* block, std::size_t roomBytes) noexcept {
    if (!block) return;
    if (mapped(roomBytes))
        munmap(block, roomBytes);
    else
        std::free(block);
}

}  // namespace g2d::rt::grow_detail
