#pragma once
// The run's only source of randomness: xoshiro256** 1.0 (Blackman & Vigna),
// seeded through SplitMix64. Every derived draw is computed here from raw
// 64-bit outputs, never with std:: distributions (whose results differ
// between standard libraries), so a seed fixes the result everywhere.
#include <cstdint>

namespace g2d::rt {

class Rng {
public:
    explicit Rng(std::uint64_t seed = 0) { reseed(seed); }
    void reseed(std::uint64_t seed);

    inline std::uint64_t next();                // raw 64 bits
    double unit();                              // [0, 1), 53 random bits
    double uniform(double a, double b);         // a + (b - a) * unit()
    // Uniform integer in [lo, hi] (inclusive), unbiased (Lemire's method with rejection).
    long long range(long long lo, long long hi);
    inline std::uint64_t below(std::uint64_t n);   // uniform in [0, n), n > 0
    // What below(n) returns when its draw is `raw`, unless it rejects that
    // draw (chance n / 2^64) and draws again: for guessing picks ahead.
    static std::uint64_t belowFrom(std::uint64_t raw, std::uint64_t n) {
        __extension__ typedef unsigned __int128 u128;
        return static_cast<std::uint64_t>((static_cast<u128>(raw) * n) >> 64);
    }
    double normal(double mean, double stddev);  // Box–Muller, one draw pair per call (the second is discarded)

private:
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    std::uint64_t s_[4];
};

// Inline: a step draws a match with them (and looks ahead with them, pick_lookahead.hpp).
std::uint64_t Rng::next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
}

std::uint64_t Rng::below(std::uint64_t n) {
    __extension__ typedef unsigned __int128 u128;
    // Lemire: multiply-shift with rejection of the biased low range.
    u128 m = static_cast<u128>(next()) * n;
    auto low = static_cast<std::uint64_t>(m);
    if (low < n) {
        const std::uint64_t threshold = (0 - n) % n;
        while (low < threshold) {
            m = static_cast<u128>(next()) * n;
            low = static_cast<std::uint64_t>(m);
        }
    }
    return static_cast<std::uint64_t>(m >> 64);
}

}  // namespace g2d::rt
