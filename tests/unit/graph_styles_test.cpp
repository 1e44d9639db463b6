// Graph style overrides: per element, replaced by property, gone with the
// element, and a removed element's list reused without leaking its entries.
#include <catch2/catch.hpp>

#include <string>

#include "g2d/graph.hpp"

using namespace g2d::rt;

namespace {
Graph twoKinds() { return Graph({KindInfo{false, false}, KindInfo{true, true}}); }
std::string text(const Value& v) { return std::get<std::string>(v); }
}  // namespace

TEST_CASE("style overrides belong to their element and go with it", "[graph][style]") {
    Graph g = twoKinds();
    const NodeId a = g.addNode(0, {0, 0}, 0), b = g.addNode(0, {1, 0}, 0);
    const EdgeId e = g.addEdge(1, a, b, 0);
    g.setNodeStyle(a, "fill", std::string("red"));
    g.setNodeStyle(a, "r", 0.5);
    g.setNodeStyle(a, "fill", std::string("blue"));   // replaces, keeps the order of first setting
    g.setEdgeStyle(e, "stroke", std::string("green"));
    REQUIRE(g.nodeStyle(a).size() == 2);
    CHECK(g.nodeStyle(a)[0].prop == "fill");
    CHECK(text(g.nodeStyle(a)[0].value) == "blue");
    CHECK(std::get<double>(g.nodeStyle(a)[1].value) == 0.5);
    CHECK(g.nodeStyle(b).empty());
    REQUIRE(g.edgeStyle(e).size() == 1);

    // Removing a drops its style and its edge's; the lists are reused by the
    // next styled elements, which see only their own entries.
    g.removeNode(a);
    CHECK(g.nodeStyle(a).empty());
    CHECK(g.edgeStyle(e).empty());
    const NodeId c = g.addNode(0, {2, 0}, 1);
    const EdgeId f = g.addEdge(1, b, c, 1);
    g.setNodeStyle(c, "stroke", std::string("black"));
    g.setEdgeStyle(f, "stroke_width", 0.1);
    REQUIRE(g.nodeStyle(c).size() == 1);
    CHECK(g.nodeStyle(c)[0].prop == "stroke");
    REQUIRE(g.edgeStyle(f).size() == 1);
    CHECK(g.edgeStyle(f)[0].prop == "stroke_width");
    CHECK(g.nodeStyle(b).empty());
}
