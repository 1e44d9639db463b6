#include "g2d/grow_array.hpp"

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <system_error>
#include <thread>
#include <sys/mman.h>
#include <unistd.h>

namespace g2d::rt::grow_detail {

namespace {

// Faults in pages of mapped arrays ahead of their writes, on its own thread
// (MADV_POPULATE_WRITE: the kernel clears and maps the pages; their contents,
// all zero, are not written, so the array's own thread may write there at
// the same time). At a million elements a run spends about a quarter of its
// time in the kernel clearing fresh pages; this moves that to the other
// core. Advice only: where the kernel lacks it, or no thread can start,
// pages are faulted in by the writes as before.
class Populator {
public:
    void post(void* from, std::size_t bytes) {
        {
            std::lock_guard lock(mutex_);
            if (broken_) return;
            queue_.emplace_back(from, bytes);
            if (!started_) {
                started_ = true;
                try {
                    std::thread([this] { run(); }).detach();
                } catch (const std::system_error&) {
                    broken_ = true;
                    queue_.clear();
                    return;
                }
            }
        }
        ready_.notify_one();
    }

private:
    void run() {
        std::unique_lock lock(mutex_);
        while (true) {
            ready_.wait(lock, [&] { return !queue_.empty(); });
            const auto [from, bytes] = queue_.front();
            queue_.pop_front();
            lock.unlock();
            // EINVAL: a kernel without it (before Linux 5.14); ENOMEM: the
            // array moved (mremap) or went meanwhile. Either way, nothing to
            // do. (Should a new mapping have taken the old place meanwhile,
            // up to a chunk of it is faulted in early: memory, never data.)
            const bool unsupported = madvise(from, bytes, MADV_POPULATE_WRITE) != 0 && errno == EINVAL;
            lock.lock();
            if (unsupported) {
                broken_ = true;
                queue_.clear();
            }
        }
    }

    std::mutex mutex_;
    std::condition_variable ready_;
    std::deque<std::pair<void*, std::size_t>> queue_;
    bool started_ = false, broken_ = false;
};

void populateAhead(void* from, std::size_t bytes) noexcept {
    // Never destroyed: its detached thread may be inside madvise at exit.
    static Populator* const populator = new Populator;
    try {
        populator->post(from, bytes);
    } catch (...) {
        // Out of memory for the queue: advice only.
    }
}

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

std::size_t settle(void* block, std::size_t roomBytes, std::size_t neededBytes, std::size_t wantedBytes) noexcept {
    if (!block || !mapped(roomBytes)) return wantedBytes;
    const std::size_t end = std::min(roomBytes, (neededBytes + kChunkBytes - 1) / kChunkBytes * kChunkBytes);
    // Only for arrays using a chunk already: a medium array would get a
    // whole huge page at its first fault, and its chunk ahead would double it.
    if (neededBytes >= kHugePage) {
        // Advice only: where the kernel has no huge pages, small ones serve.
        // The whole mapping, so that it stays one region (mremap moves only
        // one), and a mapping moved by mremap keeps it.
        madvise(block, roomBytes, MADV_HUGEPAGE);
        if (end < roomBytes) populateAhead(static_cast<char*>(block) + end, std::min(kChunkBytes, roomBytes - end));
    }
    return std::max(end, neededBytes);
}

void release(void* block, std::size_t roomBytes) noexcept {
    if (!block) return;
    if (mapped(roomBytes))
        munmap(block, roomBytes);
    else
        std::free(block);
}

}  // namespace g2d::rt::grow_detail
