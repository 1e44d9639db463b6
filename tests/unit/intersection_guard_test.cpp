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
    GraphJournal journal;
    explicit Scene(bool plane = false) : guard(plane) {
        for (vec3 p : {vec3{0, 0, 0}, vec3{1, 0, 0}, vec3{1, 1, 0}, vec3{0, 1, 0}}) square.push_back(g.addNode(0, p, 0));
        for (std::size_t i = 0; i < 4; ++i) g.addEdge(1, square[i], square[(i + 1) % 4], 0);
        g.addFace(2, square, 0);
        guard.begin(g);
    }
    // One application: an edge from `from` (a new node there, or an existing one) to a new node at `to`.
    bool addEdge(vec3 from, vec3 to, NodeId at = kNoId, double radius = 0) {
        g.beginJournal(journal);
        const NodeId a = at != kNoId ? at : g.addNode(0, from, 1);
        const NodeId b = g.addNode(0, to, 1);
        g.setRadius(a, radius);
        g.setRadius(b, radius);
        g.addEdge(1, a, b, 1);
        return guard.admit(g);
    }
    // One application: node n moved to p.
    bool move(NodeId n, vec3 p) {
        g.beginJournal(journal);
        g.setPos(n, p);
        return guard.admit(g);
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

TEST_CASE("a thick edge is kept clear of a face by its radius", "[g3][intersect]") {
    Scene s;
    // Down towards the face (z = 0) over its middle, ending 0.01 above it: radius 0.1 refuses it, 0.005 keeps it.
    CHECK_FALSE(s.addEdge({0.5, 0.5, 1}, {0.5, 0.5, 0.01}, kNoId, 0.1));
    CHECK(s.addEdge({0.5, 0.5, 1}, {0.5, 0.5, 0.2}, kNoId, 0.1));
    CHECK(s.addEdge({0.2, 0.2, 1}, {0.2, 0.2, 0.01}, kNoId, 0.005));
    // From a corner, up: touching there is not intersecting, whatever the radius.
    CHECK(s.addEdge({}, {1, 1, 1}, s.square[2], 0.3));
}

TEST_CASE("in the plane a face is an area: inside is fine, crossing its outline is not", "[g3][intersect]") {
    Scene s(true);
    CHECK(s.addEdge({0.2, 0.2, 0}, {0.8, 0.4, 0}));        // wholly inside
    CHECK(s.addEdge({}, {0.5, 0.9, 0}, s.square[0]));      // from a corner, inwards
    CHECK_FALSE(s.addEdge({0.5, 0.5, 0}, {1.5, 0.5, 0}));  // out through a side
    CHECK(s.addEdge({2, 0, 0}, {2, 1, 0}));                // outside
}

TEST_CASE("a move that would intersect is undone exactly", "[g3][intersect]") {
    Scene s;
    const NodeId a = s.g.addNode(0, vec3{0.5, 0.5, -1}, 0), b = s.g.addNode(0, vec3{2, 0.5, -1}, 0);
    s.g.addEdge(1, a, b, 0);   // a stick under the square
    s.guard.begin(s.g);
    CHECK_FALSE(s.move(b, {0.5, 0.5, 1}));   // upright, it would pierce the square
    CHECK(s.g.pos3(b) == vec3{2, 0.5, -1});
    CHECK(s.move(b, {0.5, 0.5, -2}));
    CHECK(s.g.pos3(b) == vec3{0.5, 0.5, -2});
    CHECK(s.guard.cancelled() == 1);
}

TEST_CASE("an undone split face comes back with its id, corners and place", "[g3][intersect]") {
    Scene s;
    const NodeId p = s.g.addNode(0, vec3{0.4, 0.5, -1}, 0), q = s.g.addNode(0, vec3{0.4, 0.5, -0.3}, 0);
    s.g.addEdge(1, p, q, 0);   // a stick under the square
    s.guard.begin(s.g);
    const FaceId f = 0;
    s.g.beginJournal(s.journal);
    // Split around a centre pulled down onto the stick's top.
    const NodeId c = s.g.addNode(0, vec3{0.5, 0.5, -0.75}, 1);
    for (std::size_t i = 0; i < 4; ++i) {
        const std::array<NodeId, 3> tri{s.square[i], s.square[(i + 1) % 4], c};
        s.g.addFace(2, tri, 1);
    }
    s.g.removeFace(f);
    CHECK_FALSE(s.guard.admit(s.g));
    REQUIRE(s.g.faceAlive(f));
    CHECK(s.g.faceCount() == 1);
    CHECK(s.g.facesOfKind(2).size() == 1);
    CHECK(s.g.faceCountAt(s.square[0]) == 1);
    CHECK_FALSE(s.g.nodeAlive(c));
    CornerId k = s.g.firstCorner(f);
    for (std::size_t i = 0; i < 4; ++i, k = s.g.nextCorner(k)) CHECK(s.g.cornerNode(k) == s.square[i]);
}
