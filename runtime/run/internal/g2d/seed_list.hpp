#pragma once
// The seeds of `--seeds SPEC` and the output names made from a pattern.
// SPEC is a comma-separated list of seeds and inclusive ranges A..B:
// "1..1000", "7", "1..10,20,30..35". Seeds are listed once each; the batch
// runs (and reports) them in ascending order.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace g2d::rt {

// The most seeds one batch takes: past that, split the range into shards
// (docs/compiling.md, "Many seeds and clusters").
inline constexpr std::size_t kMaxBatchSeeds = 10'000'000;

// What an output name must contain to differ from seed to seed.
inline constexpr const char* kSeedPlaceholder = "{seed}";

// The seeds of SPEC, ascending. Throws std::invalid_argument with a message
// that names the bad part (a reversed range, a duplicate, a non-number).
std::vector<std::uint64_t> parseSeedList(const std::string& spec);

bool hasSeedPlaceholder(const std::string& pattern);

// `pattern` with every {seed} replaced by the seed in decimal.
std::string withSeed(const std::string& pattern, std::uint64_t seed);

}  // namespace g2d::rt
