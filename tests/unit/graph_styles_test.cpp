// Graph style overrides: per element, replaced by property, gone with the
// element, and a removed element's entries reused without leaking into the
// next element's list.
#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

#include "g2d/graph.hpp"

using namespace g2d::rt;

namespace {
Graph twoKinds() { return Graph({KindInfo{ElemClass::Node, false}, KindInfo{ElemClass::Edge, true}}); }
std::string text(const Value& v) { return std::get<std::string>(v); }

// An element's overrides as (name, value) pairs, in their order.
std::vector<std::pair<std::string, Value>> listed(const Graph& g, StyleList list) {
    std::vector<std::pair<std::string, Value>> out;
    for (const auto& s : list) out.emplace_back(g.stylePropName(s.prop), s.value);
    return out;
}
}  // namespace

TEST_CASE("style overrides belong to their element and go with it", "[graph][style]") {
    Graph g = twoKinds();
    const NodeId a = g.addNode(0, {0, 0}, 0), b = g.addNode(0, {1, 0}, 0);
    const EdgeId e = g.addEdge(1, a, b, 0);
    g.setNodeStyle(a, "fill", std::string("red"));
    g.setNodeStyle(a, "r", 0.5);
    g.setNodeStyle(a, "fill", std::string("blue"));   // replaces, keeps the order of first setting
    g.setEdgeStyle(e, "stroke", std::string("green"));
    auto la = listed(g, g.nodeStyle(a));
    REQUIRE(la.size() == 2);
    CHECK(g.nodeStyle(a).size() == 2);
    CHECK(la[0].first == "fill");
    CHECK(text(la[0].second) == "blue");
    CHECK(la[1].first == "r");
    CHECK(std::get<double>(la[1].second) == 0.5);
    CHECK(g.nodeStyle(b).empty());
    REQUIRE(g.edgeStyle(e).size() == 1);

    // Removing a drops its style and its edge's; the entries are reused by
    // the next styled elements, which see only their own.
    g.removeNode(a);
    CHECK(g.nodeStyle(a).empty());
    CHECK(g.edgeStyle(e).empty());
    const NodeId c = g.addNode(0, {2, 0}, 1);
    const EdgeId f = g.addEdge(1, b, c, 1);
    g.setNodeStyle(c, "stroke", std::string("black"));
    g.setEdgeStyle(f, "stroke_width", 0.1);
    auto lc = listed(g, g.nodeStyle(c));
    REQUIRE(lc.size() == 1);
    CHECK(lc[0].first == "stroke");
    CHECK(text(lc[0].second) == "black");
    auto lf = listed(g, g.edgeStyle(f));
    REQUIRE(lf.size() == 1);
    CHECK(lf[0].first == "stroke_width");
    CHECK(g.nodeStyle(b).empty());
}

TEST_CASE("style properties are numbered in the program's order, new names after", "[graph][style]") {
    Graph g({KindInfo{ElemClass::Node, false}}, {"tag", "fill", "d"});
    CHECK(g.styleProp("tag") == 0);
    CHECK(g.styleProp("d") == 2);
    CHECK(g.styleProp("stroke") == 3);
    CHECK(g.styleProp("stroke") == 3);
    CHECK(g.stylePropName(1) == "fill");
    const NodeId n = g.addNode(0, {0, 0}, 0);
    g.setNodeStyle(n, StyleProp{2}, std::string("M 0 0"));
    g.setNodeStyle(n, "d", std::string("M 1 1"));   // the same property, by name
    auto l = listed(g, g.nodeStyle(n));
    REQUIRE(l.size() == 1);
    CHECK(l[0].first == "d");
    CHECK(text(l[0].second) == "M 1 1");
}

TEST_CASE("a removed element's style entries are reused, not grown", "[graph][style]") {
    // Many elements restyled and removed in turn: the pool stays at the
    // most ever alive at once (one block), where a pool growing per element
    // would take 2,000 entries (eight blocks).
    StyleStore store;
    const StyleProp fill = store.prop("fill"), r = store.prop("r");
    std::uint32_t prev = StyleStore::kNone;
    store.set(prev, fill, std::string("a"));
    store.set(prev, r, 1.0);
    const std::size_t warm = store.memoryBytes();
    for (int i = 1; i <= 1000; ++i) {
        std::uint32_t next = StyleStore::kNone;
        store.set(next, fill, std::string(100, 'x'));   // a long string, released with its element
        store.set(next, r, static_cast<double>(i));
        store.drop(prev);
        CHECK(prev == StyleStore::kNone);
        prev = next;
    }
    CHECK(store.memoryBytes() == warm);
    std::vector<std::pair<StyleProp, Value>> last;
    for (const auto& e : store.list(prev)) last.emplace_back(e.prop, e.value);
    REQUIRE(last.size() == 2);
    CHECK(last[0].first == fill);
    CHECK(std::get<std::string>(last[0].second) == std::string(100, 'x'));
    CHECK(std::get<double>(last[1].second) == 1000.0);

    // The same through a graph: the survivor's list is its own.
    Graph g = twoKinds();
    NodeId before = g.addNode(0, {0, 0}, 0);
    g.setNodeStyle(before, "fill", std::string("a"));
    for (int i = 1; i <= 100; ++i) {
        const NodeId n = g.addNode(0, {0, 0}, i);
        g.setNodeStyle(n, "r", static_cast<double>(i));
        g.removeNode(before);
        before = n;
    }
    auto l = listed(g, g.nodeStyle(before));
    REQUIRE(l.size() == 1);
    CHECK(l[0].first == "r");
    CHECK(std::get<double>(l[0].second) == 100.0);
}
