// A rule's match set under `pick oldest`, against a plain model: the matches
// with the lowest sum of creation steps, in the order their group keeps them
// (appended; a leaver's place taken by the group's last), and the match a
// draw picks among them, over random additions and removals (every match
// binding a node, as a repair drops them). The set keeps each match's place
// in its group in the match's record; a wrong place would show here as a
// group out of order or holding a match that left.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/match_set.hpp"
#include "g2d/rng.hpp"

using namespace g2d::rt;

namespace {

struct ModelMatch {
    NodeId a, b;
    EdgeId e;
    long long key;
};

// The age groups as the set should hold them: edge ids, by key.
struct OldestModel {
    std::vector<ModelMatch> live;   // in the order they were added
    std::map<long long, std::vector<EdgeId>> groups;

    void add(const ModelMatch& m) {
        live.push_back(m);
        groups[m.key].push_back(m.e);
    }
    // The set unlinks a node's matches from its list, newest first.
    void removeTouching(NodeId n) {
        for (std::size_t i = live.size(); i-- > 0;) {
            if (live[i].a != n && live[i].b != n) continue;
            auto& group = groups[live[i].key];
            auto at = std::find(group.begin(), group.end(), live[i].e);
            *at = group.back();
            group.pop_back();
            if (group.empty()) groups.erase(live[i].key);
            live.erase(live.begin() + static_cast<std::ptrdiff_t>(i));
        }
    }
};

void exercise(std::uint64_t seed, int ageSpread) {
    Rng rng(seed);
    Graph g({KindInfo{ElemClass::Node, false}, KindInfo{ElemClass::Edge, true}});
    std::vector<NodeId> nodes;
    for (int i = 0; i < 30; ++i)
        nodes.push_back(g.addNode(0, {0, 0}, static_cast<long long>(rng.below(static_cast<std::uint64_t>(ageSpread)))));
    std::vector<EdgeId> edges;
    for (int i = 0; i < 150; ++i) {
        const NodeId a = nodes[rng.below(nodes.size())];
        NodeId b = nodes[rng.below(nodes.size())];
        if (b == a) b = nodes[(a + 1) % nodes.size()];
        edges.push_back(g.addEdge(1, a, b, static_cast<long long>(rng.below(static_cast<std::uint64_t>(ageSpread)))));
    }
    MatchSet set(2, 1, 0, Pick::Oldest);
    OldestModel model;
    for (int op = 0; op < 4000; ++op) {
        if (model.live.empty() || rng.below(100) < 60) {
            const EdgeId e = edges[rng.below(edges.size())];
            const bool there = std::any_of(model.live.begin(), model.live.end(), [&](const ModelMatch& m) { return m.e == e; });
            if (there) continue;
            const NodeId ns[2] = {g.source(e), g.target(e)};
            const EdgeId es[1] = {e};
            set.add(ns, es, g);
            model.add(ModelMatch{ns[0], ns[1], e, g.nodeAge(ns[0]) + g.nodeAge(ns[1]) + g.edgeAge(e)});
        } else {
            const NodeId n = nodes[rng.below(nodes.size())];
            set.removeTouching(n);
            model.removeTouching(n);
        }
        REQUIRE(set.size() == model.live.size());
        if (model.live.empty()) continue;
        // The lowest group, member by member.
        const auto& [key, expected] = *model.groups.begin();
        std::uint64_t lowest[1];
        REQUIRE(set.ageGroups().peekLowest(lowest, 1) == 1);
        REQUIRE(lowest[0] == static_cast<std::uint64_t>(key));
        std::vector<EdgeId> held;
        for (const std::uint32_t id : set.ageGroups().groupIds(lowest[0])) held.push_back(set.matchOf(id).edges[0]);
        REQUIRE(held == expected);
        // The pick: no draw for a group of one, else below(k) over its order.
        Rng draws(seed * 1000 + static_cast<std::uint64_t>(op)), same = draws;
        const EdgeId picked = set.pickOldest(draws).edges[0];
        REQUIRE(picked == (expected.size() == 1 ? expected[0] : expected[same.below(expected.size())]));
    }
}

}  // namespace

TEST_CASE("oldest picks come from the lowest age group, in the group's order", "[match_set][oldest]") {
    exercise(1, 3);    // ages 0..2: large groups of ties, spilled past three
    exercise(2, 40);   // mostly groups of one or two
}
