#pragma once
// Asking the processor to load a cache line ahead of its use.
//
// Not `__builtin_prefetch` in the helpers that only prefetch: GCC's
// pure-const analysis counts the builtin as free of side effects, finds a
// function holding nothing else "pure", and deletes every call to it (it
// returns nothing). That silently removed the pick lookahead's prefetches
// (`MatchSet::prefetchPosition`, `prefetchRecordAt`, `AgeBuckets::prefetchGroup`):
// their calls were not in the object code at all. A volatile asm statement is
// a side effect the compiler keeps, wherever it ends up inlined. It takes
// the address in a register, not as a memory operand: nothing is
// dereferenced, so an address past an array's end (the appends' write-ahead)
// is no access for the sanitizers.

#include <cstddef>
#include <cstdint>

namespace g2d::rt {

// For reading, into every cache level.
inline void prefetchLine(const void* p) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    asm volatile("prefetcht0 (%0)" : : "r"(p));
#else
    __builtin_prefetch(p, 0, 3);
#endif
}

// Every line of a record of `bytes` bytes at `p` (a 48-byte node record
// straddles two lines in every other place).
inline void prefetchRecordLines(const void* p, std::size_t bytes) {
    const auto first = reinterpret_cast<std::uintptr_t>(p);
    const auto* line = static_cast<const char*>(p);
    prefetchLine(line);
    for (std::uintptr_t rest = (first & 63) + bytes; rest > 64; rest -= 64) {
        line += 64;
        prefetchLine(line);
    }
}

// For writing (an append stream the hardware does not run ahead of).
inline void prefetchLineForWrite(const void* p) {
#if defined(__x86_64__) && defined(__PRFCHW__) && (defined(__GNUC__) || defined(__clang__))
    asm volatile("prefetchw (%0)" : : "r"(p));
#elif defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    asm volatile("prefetcht0 (%0)" : : "r"(p));
#else
    __builtin_prefetch(p, 1, 3);
#endif
}

}  // namespace g2d::rt
