#include "g2d/grow_array.hpp"

#include <cstdlib>
#include <sys/mman.h>
#include <unistd.h>

namespace g2d::rt::grow_detail {

namespace {

std::size_t pageRounded(std::size_t bytes) {
    static const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    return (bytes + page - 1) / page * page;
}

bool mapped(std::size_t bytes) { return bytes >= kMappedBytes; }

void* map(std::size_t bytes) {
    void* p = mmap(nullptr, pageRounded(bytes), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    return p;
}

}  // namespace

void* resize(void* block, std::size_t oldBytes, std::size_t newBytes, std::size_t usedBytes) {
    if (!mapped(newBytes)) {
        // Small: malloc's realloc (the old block is small too: arrays only grow).
        void* p = std::realloc(block, newBytes);
        if (!p) throw std::bad_alloc();
        return p;
    }
    if (block && mapped(oldBytes)) {
        // The kernel moves the pages; nothing is copied.
        void* p = mremap(block, pageRounded(oldBytes), pageRounded(newBytes), MREMAP_MAYMOVE);
        if (p == MAP_FAILED) throw std::bad_alloc();
        return p;
    }
    void* p = map(newBytes);
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
