// AgeBuckets against a plain model (a sorted map of key -> ids, with the same
// append / take-the-last's-place order inside a group): random inserts and
// erases over clustered and scattered keys, crossing page boundaries, with
// pages and groups emptied and reused.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <vector>

#include "g2d/age_buckets.hpp"
#include "g2d/rng.hpp"

namespace {

struct Model {
    std::map<long long, std::vector<std::uint32_t>> groups;
    std::map<std::uint32_t, long long> keyOf;
    void insert(std::uint32_t id, long long key) {
        groups[key].push_back(id);
        keyOf[id] = key;
    }
    void erase(std::uint32_t id) {
        auto& ids = groups[keyOf[id]];
        auto at = std::find(ids.begin(), ids.end(), id);
        *at = ids.back();
        ids.pop_back();
        if (ids.empty()) groups.erase(keyOf[id]);
        keyOf.erase(id);
    }
};

void exercise(std::uint64_t seed, long long keySpread, int operations) {
    g2d::rt::Rng rng(seed);
    g2d::rt::AgeBuckets buckets;
    Model model;
    std::vector<std::uint32_t> live, freeIds;
    // What a caller keeps per id: its key and its place in its group.
    std::map<std::uint32_t, std::pair<long long, std::uint32_t>> placeOf;
    std::uint32_t nextId = 0;
    long long base = 0;
    for (int op = 0; op < operations; ++op) {
        const bool insert = live.empty() || rng.below(100) < 55;
        if (insert) {
            std::uint32_t id;
            if (!freeIds.empty() && rng.below(2) == 0) {
                id = freeIds.back();
                freeIds.pop_back();
            } else {
                id = nextId++;
            }
            // Mostly near a slowly rising base (as matches of recent steps),
            // sometimes anywhere below it (a match of old elements).
            base += static_cast<long long>(rng.below(3));
            const long long key = rng.below(10) == 0 ? static_cast<long long>(rng.below(static_cast<std::uint64_t>(base + 1)))
                                                     : base + static_cast<long long>(rng.below(static_cast<std::uint64_t>(keySpread)));
            placeOf[id] = {key, buckets.insert(id, key)};
            REQUIRE(placeOf[id].second == model.groups[key].size());
            model.insert(id, key);
            live.push_back(id);
        } else {
            // Often the lowest group's members (as a derivation takes them).
            std::uint32_t id;
            if (rng.below(2) == 0) {
                const auto& low = model.groups.begin()->second;
                id = low[static_cast<std::size_t>(rng.below(low.size()))];
            } else {
                id = live[static_cast<std::size_t>(rng.below(live.size()))];
            }
            const auto [key, place] = placeOf[id];
            const std::uint32_t moved = buckets.erase(static_cast<std::uint64_t>(key), place);
            placeOf.erase(id);
            const bool wasLast = model.groups[key].back() == id;
            REQUIRE((moved == g2d::rt::AgeBuckets::kNoMove) == wasLast);
            if (!wasLast) {
                REQUIRE(moved == model.groups[key].back());
                placeOf[moved].second = place;
            }
            model.erase(id);
            live.erase(std::find(live.begin(), live.end(), id));
            freeIds.push_back(id);
        }
        REQUIRE(buckets.empty() == model.groups.empty());
        if (!model.groups.empty()) {
            const auto low = buckets.lowest();
            REQUIRE(std::vector<std::uint32_t>(low.begin(), low.end()) == model.groups.begin()->second);
            // The lookahead's view: the lowest keys of the lowest page, in order.
            std::uint64_t keys[4];
            const std::size_t found = buckets.peekLowest(keys, 4);
            REQUIRE(found >= 1);
            auto group = model.groups.begin();
            for (std::size_t i = 0; i < found; ++i, ++group) {
                REQUIRE(keys[i] == static_cast<std::uint64_t>(group->first));
                const auto ids = buckets.groupIds(keys[i]);
                REQUIRE(std::vector<std::uint32_t>(ids.begin(), ids.end()) == group->second);
                for (std::uint32_t at = 0; at < ids.size(); ++at) REQUIRE(placeOf[ids[at]].second == at);
            }
            // Fewer than asked only when the next key is on another page (1024 keys each).
            if (found < 4 && group != model.groups.end()) REQUIRE(group->first / 1024 != model.groups.begin()->first / 1024);
        }
    }
}

}  // namespace

TEST_CASE("age buckets give the lowest group, in the model's order", "[age_buckets]") {
    exercise(1, 8, 20000);         // clustered: many ties
    exercise(2, 3000, 20000);      // spread over several pages
    exercise(3, 1, 5000);          // one key at a time
}

TEST_CASE("age buckets reject a negative key", "[age_buckets]") {
    g2d::rt::AgeBuckets buckets;
    CHECK_THROWS_AS(buckets.insert(0, -1), std::logic_error);
}
