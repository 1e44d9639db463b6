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

    std::uint64_t next();                       // raw 64 bits
    double unit();                              // [0, 1), 53 random bits
    double uniform(double a, double b);         // a + (b - a) * unit()
    // Uniform integer in [lo, hi] (inclusive), unbiased (Lemire's method with rejection).
    long long range(long long lo, long long hi);
    std::uint64_t below(std::uint64_t n);       // uniform in [0, n), n > 0
    double normal(double mean, double stddev);  // Box–Muller, one draw pair per call (the second is discarded)

private:
    std::uint64_t s_[4];
};

}  // namespace g2d::rt
