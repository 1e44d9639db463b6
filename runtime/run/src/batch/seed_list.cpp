#include "g2d/seed_list.hpp"

#include <algorithm>
#include <charconv>

namespace g2d::rt {

namespace {

std::uint64_t parseSeed(const std::string& text, const std::string& spec) {
    std::uint64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (text.empty() || ec != std::errc{} || ptr != end)
        throw std::invalid_argument("--seeds " + spec + ": `" + text +
                                    "` is not a seed (write seeds and ranges like 1..100,200,300..310)");
    return value;
}

}  // namespace

std::vector<std::uint64_t> parseSeedList(const std::string& spec) {
    std::vector<std::uint64_t> seeds;
    std::size_t from = 0;
    while (true) {
        const std::size_t comma = std::min(spec.find(',', from), spec.size());
        const std::string part = spec.substr(from, comma - from);
        const std::size_t dots = part.find("..");
        const std::uint64_t first = parseSeed(part.substr(0, dots), spec);
        const std::uint64_t last = dots == std::string::npos ? first : parseSeed(part.substr(dots + 2), spec);
        if (last < first)
            throw std::invalid_argument("--seeds " + spec + ": the range " + part + " is empty (write the smaller seed first)");
        if (last - first >= kMaxBatchSeeds || seeds.size() + (last - first) >= kMaxBatchSeeds)
            throw std::invalid_argument("--seeds " + spec + ": more than " + std::to_string(kMaxBatchSeeds) +
                                        " seeds; run the range in shards (one batch per shard)");
        for (std::uint64_t s = first;; ++s) {
            seeds.push_back(s);
            if (s == last) break;
        }
        if (comma == spec.size()) break;
        from = comma + 1;
    }
    std::sort(seeds.begin(), seeds.end());
    if (const auto twice = std::adjacent_find(seeds.begin(), seeds.end()); twice != seeds.end())
        throw std::invalid_argument("--seeds " + spec + ": seed " + std::to_string(*twice) + " is listed twice");
    return seeds;
}

bool hasSeedPlaceholder(const std::string& pattern) { return pattern.find(kSeedPlaceholder) != std::string::npos; }

std::string withSeed(const std::string& pattern, std::uint64_t seed) {
    const std::string placeholder = kSeedPlaceholder, number = std::to_string(seed);
    std::string out;
    std::size_t from = 0;
    for (std::size_t at; (at = pattern.find(placeholder, from)) != std::string::npos; from = at + placeholder.size())
        out += pattern.substr(from, at - from) + number;
    return out + pattern.substr(from);
}

}  // namespace g2d::rt
