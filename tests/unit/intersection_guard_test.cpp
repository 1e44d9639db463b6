// G^3's intersection tests as the derivation runs them (intersection_guard.hpp):
// an application's additions are kept, or removed when they would cut
// through the model; touching at a shared node is not cutting.
#include <catch2/catch.hpp>

#include "g2d/intersection_guard.hpp"

using namespace g2d::rt;

namespace {

// Kinds: 0 node, 1 edge, 2 face. A unit square face in z = 0.
struct Scene {
    Graph g{{KindInfo{ElemClass::Node, false}, KindInfo{ElemClass::Edge, true}, KindInfo{ElemClass::Face, false}}};
    std::vector<NodeId> square;
    IntersectionGuard guard;
    Scene() {
        for (vec3 p : {vec3{0, 0, 0}, vec3{1, 0, 0}, vec3{1, 1, 0}, vec3{0, 1, 0}}) square.push_back(g.addNode(0, p, 0));
        for (std::size_t i = 0; i < 4; ++i) g.addEdge(1, square[i], square[(i + 1) % 4], 0);
        g.addFace(2, square, 0);
        guard.begin(g);
    }
    // One application: an edge from `from` (a new node there, or an existing one) to a new node at `to`.
    bool addEdge(vec3 from, vec3 to, NodeId at = kNoId, double radius = 0) {
        const auto before = IntersectionGuard::capacities(g);
        const NodeId a = at != kNoId ? at : g.addNode(0, from, 1);
        const NodeId b = g.addNode(0, to, 1);
        g.setRadius(a, radius);
        g.setRadius(b, radius);
        g.addEdge(1, a, b, 1);
        return guard.admit(g, before, IntersectionGuard::capacities(g));
    }
};

}  // namespace

TEST_CASE("an edge through a face is undone, with its nodes", "[g3][intersect]") {
    Scene s;
    const std::size_t nodes = s.g.nodeCount(), edges = s.g.edgeCount();
    CHECK_FALSE(s.addEdge({0.5, 0.5, -1}, {0.5, 0.5, 1}));
    CHECK(s.g.nodeCount() == nodes);
    CHECK(s.g.edgeCount() == edges);
    CHECK(s.guard.cancelled() == 1);
}

TEST_CASE("an edge from a corner of a face, or beside it, is kept", "[g3][intersect]") {
    Scene s;
    CHECK(s.addEdge({}, {0, 0, 1}, s.square[0]));      // up from a corner: touches the face there only
    CHECK(s.addEdge({}, {-1, -1, 0}, s.square[0]));    // outwards in the face's plane
    CHECK(s.addEdge({2, 0, -1}, {2, 0, 1}));           // past the face
    CHECK(s.guard.cancelled() == 0);
}

TEST_CASE("an edge lying across a face in its plane is undone", "[g3][intersect]") {
    Scene s;
    CHECK_FALSE(s.addEdge({}, {1, 1, 0}, s.square[0]));   // the diagonal: inside the face
}

TEST_CASE("edges without faces are cylinders of their nodes' radii", "[g3][intersect]") {
    Scene s;
    REQUIRE(s.addEdge({3, 0, 0}, {3, 0, 1}, kNoId, 0.02));
    CHECK_FALSE(s.addEdge({3.03, 0, 0}, {3.03, 0, 1}, kNoId, 0.02));   // axes 0.03 apart, radii 0.02 + 0.02
    CHECK(s.addEdge({3.05, 0, 0}, {3.05, 0, 1}, kNoId, 0.02));         // 0.05 apart: clear
}

TEST_CASE("a step's later application is tested against its earlier, kept ones", "[g3][intersect]") {
    Scene s;
    REQUIRE(s.addEdge({5, 0, 0}, {5, 2, 0}));
    CHECK_FALSE(s.addEdge({4, 1, 0}, {6, 1, 0}));   // crosses the edge just kept
}
