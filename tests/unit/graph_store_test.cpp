// The graph store's indexes: the edge kinds a node has had, and the live
// nodes in id order.
#include <catch2/catch.hpp>

#include <vector>

#include "g2d/graph.hpp"

using namespace g2d::rt;

TEST_CASE("a node's edge kinds gain a bit per linked kind and keep it", "[graph]") {
    // Kinds 0: node, 1 and 2: edges, 33: an edge kind sharing kind 1's bit.
    std::vector<KindInfo> kinds(34, KindInfo{ElemClass::Edge, true});
    kinds[0] = KindInfo{ElemClass::Node, false};
    Graph g(kinds);
    const NodeId a = g.addNode(0, {0, 0}, 0), b = g.addNode(0, {1, 0}, 0), c = g.addNode(0, {2, 0}, 0);
    CHECK(g.edgeKindsAt(a) == 0);
    const EdgeId ab = g.addEdge(1, a, b, 0);
    CHECK(g.edgeKindsAt(a) == Graph::edgeKindBit(1));
    CHECK(g.edgeKindsAt(b) == Graph::edgeKindBit(1));
    g.addEdge(2, b, c, 0);
    CHECK(g.edgeKindsAt(b) == (Graph::edgeKindBit(1) | Graph::edgeKindBit(2)));
    CHECK(g.edgeKindsAt(c) == Graph::edgeKindBit(2));
    g.removeEdge(ab);   // a superset: the bit stays
    CHECK(g.edgeKindsAt(a) == Graph::edgeKindBit(1));
    const EdgeId ca = g.addEdge(33, c, a, 0);
    CHECK(Graph::edgeKindBit(33) == Graph::edgeKindBit(1));
    g.reconnectEdge(ca, c, c);   // a moved edge marks its new ends
    CHECK(g.edgeKindsAt(c) == (Graph::edgeKindBit(2) | Graph::edgeKindBit(33)));
}

TEST_CASE("allNodes lists the live nodes by id", "[graph]") {
    Graph g({KindInfo{ElemClass::Node, false}, KindInfo{ElemClass::Node, false}, KindInfo{ElemClass::Edge, false}});
    for (int i = 0; i < 6; ++i) g.addNode(i % 2, {0, 0}, 0);
    g.addEdge(2, 0, 1, 0);
    g.removeNode(0);
    g.removeNode(3);
    g.removeNode(5);
    std::vector<NodeId> live;
    for (NodeId n : g.allNodes()) live.push_back(n);
    CHECK(live == std::vector<NodeId>{1, 2, 4});
    CHECK(g.nodeCount() == 3);
}
