#pragma once
// A growable array of trivially copyable records, for the columns that grow
// with the graph (node and edge records, kind indexes, match sets).
//
// std::vector grows by allocating a larger block and copying every element:
// at millions of elements that reads and writes the whole array again (cache
// misses that made a derivation step slower the larger the graph was) and
// briefly holds both copies (peak memory). Here an array past 64 KiB lives in
// its own anonymous memory mapping, which reserves address space ahead and
// grows past that with mremap, which moves page tables, not records; only
// pages that are written take memory. Small arrays use realloc. Elements
// are never constructed by default, only by the operations that add them.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#include "g2d/prefetch.hpp"

namespace g2d::rt {

namespace grow_detail {
// Makes room for at least `newBytes`, keeping the first `usedBytes` of
// `block` (which has room for `roomBytes`; nullptr and 0 for none), and sets
// `roomBytes` to the room of the block returned; throws std::bad_alloc.
// Below kMappedBytes blocks come from malloc. Larger ones are memory
// mappings that reserve address space ahead (kReservedBytes at least):
// growing within one costs nothing, and a page takes memory only when first
// written (no copy, no page touched twice).
void* grow(void* block, std::size_t& roomBytes, std::size_t newBytes, std::size_t usedBytes);
// The room an array needing `neededBytes` takes of its block next (at
// least that; `wantedBytes` when the block is malloc's). A mapped block is
// taken a 2 MiB chunk at a time: each time, the next chunk's pages are
// faulted in by a helper thread (populateAhead), so that the kernel clears
// them on the other core rather than in this thread's first writes. Also
// asks for huge pages once the array takes 2 MiB or more: small arrays keep
// small pages, as a huge one would be 2 MiB of memory to clear.
std::size_t settle(void* block, std::size_t roomBytes, std::size_t neededBytes, std::size_t wantedBytes) noexcept;
inline constexpr std::size_t kChunkBytes = std::size_t{2} << 20;
void release(void* block, std::size_t roomBytes) noexcept;
// Under AddressSanitizer every block comes from malloc, so that overruns are caught.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr std::size_t kMappedBytes = ~std::size_t{0};
#else
inline constexpr std::size_t kMappedBytes = std::size_t{64} << 10;
#endif
inline constexpr std::size_t kReservedBytes = std::size_t{64} << 20;
// Room that puts an array in its own mapping at once (a page where every
// block is malloc's), for columns known to grow large.
inline constexpr std::size_t kOwnMappingBytes = kMappedBytes == ~std::size_t{0} ? 4096 : kMappedBytes;
}  // namespace grow_detail

template <class T>
class GrowArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "GrowArray moves its records as bytes");

public:
    using value_type = T;
    using iterator = T*;
    using const_iterator = const T*;

    GrowArray() = default;
    GrowArray(const GrowArray& other) { append(other.begin(), other.end()); }
    GrowArray(GrowArray&& other) noexcept
        : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)),
          capacity_(std::exchange(other.capacity_, 0)), room_(std::exchange(other.room_, 0)) {}
    GrowArray& operator=(GrowArray other) noexcept {
        swap(other);
        return *this;
    }
    ~GrowArray() { grow_detail::release(data_, room_); }
    void swap(GrowArray& other) noexcept {
        std::swap(data_, other.data_);
        std::swap(size_, other.size_);
        std::swap(capacity_, other.capacity_);
        std::swap(room_, other.room_);
    }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    std::size_t capacity() const { return capacity_; }
    T* data() { return data_; }
    const T* data() const { return data_; }
    T* begin() { return data_; }
    T* end() { return data_ + size_; }
    const T* begin() const { return data_; }
    const T* end() const { return data_ + size_; }
    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    T& back() { return data_[size_ - 1]; }
    const T& back() const { return data_[size_ - 1]; }

    void push_back(const T& value) {
        prefetchAhead();
        if (size_ == capacity_) {
            const T copy = value;   // `value` may live in this array
            reserve(size_ + 1);
            ::new (static_cast<void*>(data_ + size_)) T(copy);
        } else {
            ::new (static_cast<void*>(data_ + size_)) T(value);
        }
        ++size_;
    }
    template <class... Args>
    T& emplace_back(Args&&... args) {
        prefetchAhead();
        if (size_ == capacity_) {
            const T made{std::forward<Args>(args)...};   // the arguments may live in this array
            reserve(size_ + 1);
            ::new (static_cast<void*>(data_ + size_)) T(made);
        } else {
            ::new (static_cast<void*>(data_ + size_)) T{std::forward<Args>(args)...};
        }
        return data_[size_++];
    }
    // Appends [first, last), which must not point into this array.
    void append(const T* first, const T* last) {
        const auto n = static_cast<std::size_t>(last - first);
        if (n == 0) return;
        reserve(size_ + n);
        std::memcpy(static_cast<void*>(data_ + size_), first, n * sizeof(T));
        size_ += n;
    }
    // Appends `n` elements left unset, for the caller to write at once
    // (no fill that would only be overwritten); returns the first.
    T* extendUnset(std::size_t n) {
        prefetchAhead();
        reserve(size_ + n);
        T* first = data_ + size_;
        size_ += n;
        return first;
    }
    void pop_back() { --size_; }
    void clear() { size_ = 0; }
    // Grows (new elements are copies of `fill`) or shrinks to `n` elements.
    void resize(std::size_t n, const T& fill = T{}) {
        const T copy = fill;
        reserve(n);
        for (std::size_t i = size_; i < n; ++i) ::new (static_cast<void*>(data_ + i)) T(copy);
        size_ = n;
    }
    void assign(std::size_t n, const T& fill) {
        clear();
        resize(n, fill);
    }
    // At least `n` elements of room; grows geometrically, from 256 bytes:
    // a grammar of many rules keeps dozens of small arrays, and when each
    // started at 4 KiB they spread over as many fresh pages, each a page
    // fault (about 2 µs here) on first touch, which dominated small runs.
    void reserve(std::size_t n) {
        if (n <= capacity_) return;
        std::size_t wanted = std::max<std::size_t>({n, capacity_ * 2, kFirstCapacity});
        if (wanted > max_size()) {
            if (n > max_size()) throw std::bad_alloc();
            wanted = max_size();
        }
        if (wanted * sizeof(T) > room_)
            data_ = static_cast<T*>(grow_detail::grow(data_, room_, wanted * sizeof(T), size_ * sizeof(T)));
        capacity_ = grow_detail::settle(data_, room_, n * sizeof(T), wanted * sizeof(T)) / sizeof(T);
    }
    static constexpr std::size_t max_size() { return (std::size_t{1} << 46) / sizeof(T); }

private:
    // The line kWriteAhead elements on, its address computed as an integer:
    // it may lie past the array, which may not exist yet (a prefetch of any
    // address is harmless; pointer arithmetic past the end is not).
    void prefetchAhead() const {
        prefetchLineForWrite(reinterpret_cast<const void*>(reinterpret_cast<std::uintptr_t>(data_) + (size_ + kWriteAhead) * sizeof(T)));
    }
    static constexpr std::size_t kWriteAhead = std::max<std::size_t>(1, 512 / sizeof(T));
    static constexpr std::size_t kFirstCapacity = std::max<std::size_t>(4, 256 / sizeof(T));
    T* data_ = nullptr;
    std::size_t size_ = 0;
    std::size_t capacity_ = 0;   // elements: grows geometrically, or a chunk at a time in a mapping
    std::size_t room_ = 0;       // bytes the block has room for (a mapping's reservation)
};

}  // namespace g2d::rt
