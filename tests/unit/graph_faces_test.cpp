// The graph store's faces: corner cycles threaded through their nodes'
// corner lists, SPO deletion, side and neighbour queries, geometry and
// change records.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/ops.hpp"
#include "g2d/rng.hpp"

using namespace g2d::rt;

namespace {

// Kinds: 0 node, 1 edge, 2 and 3 faces.
Graph makeGraph() {
    return Graph({KindInfo{ElemClass::Node, false}, KindInfo{ElemClass::Edge, false}, KindInfo{ElemClass::Face, false},
                  KindInfo{ElemClass::Face, false}});
}

std::vector<NodeId> cornersOf(const Graph& g, FaceId f) {
    std::vector<NodeId> out;
    CornerId c = g.firstCorner(f);
    for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) out.push_back(g.cornerNode(c));
    return out;
}

// Every structural invariant of the face store (docs/architecture.md, "Faces").
void checkInvariants(const Graph& g) {
    std::size_t live = 0;
    std::map<NodeId, int> cornersPerNode;
    for (FaceId f = 0; f < g.faceCapacity(); ++f) {
        if (!g.faceAlive(f)) continue;
        ++live;
        const int k = g.cornerCount(f);
        REQUIRE(k >= 3);
        std::set<NodeId> seen;
        CornerId c = g.firstCorner(f);
        for (int i = 0; i < k; ++i, c = g.nextCorner(c)) {
            REQUIRE(g.cornerFace(c) == f);
            REQUIRE(g.nextCorner(g.prevCorner(c)) == c);
            REQUIRE(g.nodeAlive(g.cornerNode(c)));
            REQUIRE(seen.insert(g.cornerNode(c)).second);   // distinct
            ++cornersPerNode[g.cornerNode(c)];
        }
        REQUIRE(c == g.firstCorner(f));   // the cycle closes after k corners
        const auto& ofKind = g.facesOfKind(g.faceKind(f));
        REQUIRE(std::count(ofKind.begin(), ofKind.end(), f) == 1);
    }
    REQUIRE(g.faceCount() == live);
    for (NodeId n = 0; n < g.nodeCapacity(); ++n) {
        int listed = 0;
        for (CornerId c = g.firstCornerAt(n); c != kNoId; c = g.nextCornerAt(c)) {
            REQUIRE(g.cornerNode(c) == n);
            REQUIRE(g.faceAlive(g.cornerFace(c)));
            ++listed;
        }
        REQUIRE(listed == g.faceCountAt(n));
        REQUIRE(listed == cornersPerNode[n]);
    }
    std::size_t indexed = 0;
    for (int kind : {2, 3}) indexed += g.facesOfKind(kind).size();
    REQUIRE(indexed == live);
}

}  // namespace

TEST_CASE("a face is a cycle of its corners, listed at each corner", "[graph][faces]") {
    Graph g = makeGraph();
    const NodeId a = g.addNode(0, {0, 0}, 0), b = g.addNode(0, {1, 0}, 0), c = g.addNode(0, {1, 1}, 0),
                 d = g.addNode(0, {0, 1}, 0);
    const NodeId quad[] = {a, b, c, d};
    const FaceId f = g.addFace(2, quad, 3);
    CHECK(cornersOf(g, f) == std::vector<NodeId>{a, b, c, d});
    CHECK(g.cornerCount(f) == 4);
    CHECK(g.faceAge(f) == 3);
    CHECK(g.faceKind(f) == 2);
    CHECK(g.faceCount() == 1);
    CHECK(g.faceCountAt(a) == 1);
    CHECK(g.cornerNode(g.prevCorner(g.firstCorner(f))) == d);
    checkInvariants(g);
}

TEST_CASE("faces on a side, with their direction, and neighbours", "[graph][faces]") {
    // A unit square split along a-c into two counter-clockwise triangles,
    // and a third face on side a-b from below.
    Graph g = makeGraph();
    const NodeId a = g.addNode(0, {0, 0}, 0), b = g.addNode(0, {1, 0}, 0), c = g.addNode(0, {1, 1}, 0),
                 d = g.addNode(0, {0, 1}, 0), e = g.addNode(0, {0.5, -1}, 0);
    const NodeId t1[] = {a, b, c}, t2[] = {a, c, d}, t3[] = {a, e, b};
    const FaceId f1 = g.addFace(2, t1, 0), f2 = g.addFace(3, t2, 0), f3 = g.addFace(2, t3, 0);
    std::vector<std::pair<FaceId, bool>> uses;
    g.eachSideUse(a, c, [&](FaceId f, bool forward) { uses.emplace_back(f, forward); });
    std::sort(uses.begin(), uses.end());
    CHECK(uses == std::vector<std::pair<FaceId, bool>>{{f1, false}, {f2, true}});   // f1 runs c -> a, f2 a -> c
    uses.clear();
    g.eachSideUse(c, a, [&](FaceId f, bool forward) { uses.emplace_back(f, forward); });
    std::sort(uses.begin(), uses.end());
    CHECK(uses == std::vector<std::pair<FaceId, bool>>{{f1, true}, {f2, false}});
    CHECK(g.sideFaceCount(a, b) == 2);
    CHECK(g.sideFaceCount(b, d) == 0);
    std::vector<FaceId> around;
    g.neighbours(f1, around);
    CHECK(around == std::vector<FaceId>{f3, f2});   // in the order of f1's sides: a-b, b-c, c-a
    CHECK(g.neighbourCount(f2) == 1);
    CHECK(g.neighbourCount(f3) == 1);
    checkInvariants(g);
}

TEST_CASE("face geometry: signed area, perimeter, corner mean", "[graph][faces]") {
    Graph g = makeGraph();
    const NodeId a = g.addNode(0, {0, 0}, 0), b = g.addNode(0, {2, 0}, 0), c = g.addNode(0, {2, 1}, 0),
                 d = g.addNode(0, {0, 1}, 0);
    const NodeId ccw[] = {a, b, c, d}, cw[] = {a, d, c, b};
    const FaceId f = g.addFace(2, ccw, 0), h = g.addFace(2, cw, 0);
    CHECK(g.signedArea(f) == 2.0);
    CHECK(g.signedArea(h) == -2.0);
    CHECK(g.area(h) == 2.0);
    CHECK(g.perimeter(f) == 6.0);
    CHECK(g.centroid(f).x == 1.0);
    CHECK(g.centroid(f).y == 0.5);
    g.setPos(c, {4, 1});   // a corner moves: the geometry follows
    CHECK(g.signedArea(f) == 3.0);
}

TEST_CASE("a face needs three distinct live corners", "[graph][faces]") {
    Graph g = makeGraph();
    const NodeId a = g.addNode(0, {0, 0}, 0), b = g.addNode(0, {1, 0}, 0), c = g.addNode(0, {1, 1}, 0);
    const NodeId two[] = {a, b}, repeated[] = {a, b, a}, ok[] = {a, b, c};
    CHECK_THROWS_WITH(g.addFace(2, two, 0), "a face needs at least 3 corners, got 2");
    CHECK_THROWS_WITH(g.addFace(2, repeated, 0), "a face's corners must be distinct nodes");
    g.removeNode(c);
    CHECK_THROWS_WITH(g.addFace(2, ok, 0), "a corner of a face is not a live node");
    CHECK(g.faceCount() == 0);
    checkInvariants(g);
}

TEST_CASE("SPO: a removed node takes its faces, a removed edge none", "[graph][faces]") {
    Graph g = makeGraph();
    const NodeId a = g.addNode(0, {0, 0}, 0), b = g.addNode(0, {1, 0}, 0), c = g.addNode(0, {1, 1}, 0),
                 d = g.addNode(0, {0, 1}, 0);
    const EdgeId ab = g.addEdge(1, a, b, 0);
    const NodeId t1[] = {a, b, c}, t2[] = {a, c, d};
    const FaceId f1 = g.addFace(2, t1, 0), f2 = g.addFace(2, t2, 0);
    g.removeEdge(ab);
    CHECK(g.faceAlive(f1));
    CHECK(g.faceCount() == 2);
    g.removeNode(b);
    CHECK_FALSE(g.faceAlive(f1));
    CHECK(g.faceAlive(f2));
    CHECK(g.faceCountAt(a) == 1);
    CHECK(g.faceCountAt(c) == 1);
    g.removeFace(f2);   // nodes and edges stay
    CHECK(g.faceCount() == 0);
    CHECK(g.nodeCount() == 3);
    CHECK(g.faceCountAt(a) == 0);
    checkInvariants(g);
}

TEST_CASE("face changes are recorded until forgotten", "[graph][faces]") {
    Graph g = makeGraph();
    g.setKindDefaults(2, {Value{0LL}});
    const NodeId a = g.addNode(0, {0, 0}, 0), b = g.addNode(0, {1, 0}, 0), c = g.addNode(0, {1, 1}, 0);
    const NodeId t[] = {a, b, c};
    const FaceId f = g.addFace(2, t, 0);
    CHECK(std::vector<FaceId>(g.changedFaces().begin(), g.changedFaces().end()) == std::vector<FaceId>{f});
    g.forgetChanges();
    CHECK(g.changedFaces().empty());
    CHECK(std::get<long long>(g.faceAttr(f, 0)) == 0);
    g.setFaceAttr(f, 0, Value{7LL});
    g.setFaceAttr(f, 0, Value{8LL});   // recorded once
    CHECK(g.changedFaces().size() == 1);
    CHECK(std::get<long long>(g.faceAttr(f, 0)) == 8);
    g.forgetChanges();
    g.removeNode(a);
    CHECK(std::vector<FaceId>(g.changedFaces().begin(), g.changedFaces().end()) == std::vector<FaceId>{f});
}

TEST_CASE("faces keep their invariants through random additions and removals", "[graph][faces]") {
    Graph g = makeGraph();
    Rng rng(7);
    std::vector<NodeId> nodes;
    for (int i = 0; i < 40; ++i) nodes.push_back(g.addNode(0, {rng.unit(), rng.unit()}, 0));
    for (int round = 0; round < 2000; ++round) {
        const auto choice = rng.below(10);
        if (choice < 6) {   // a face on 3..6 distinct live nodes
            std::vector<NodeId> live;
            for (NodeId n : nodes)
                if (g.nodeAlive(n)) live.push_back(n);
            const std::size_t k = 3 + rng.below(4);
            if (live.size() < k) continue;
            std::vector<NodeId> corners;
            while (corners.size() < k) {
                const NodeId n = live[rng.below(live.size())];
                if (std::find(corners.begin(), corners.end(), n) == corners.end()) corners.push_back(n);
            }
            g.addFace(2 + static_cast<int>(rng.below(2)), corners, round);
        } else if (choice < 9) {   // remove a random live face
            if (g.faceCount() == 0) continue;
            FaceId f;
            do f = static_cast<FaceId>(rng.below(g.faceCapacity()));
            while (!g.faceAlive(f));
            g.removeFace(f);
        } else {   // remove a node (its faces go) and add a fresh one
            g.removeNode(nodes[rng.below(nodes.size())]);
            nodes.push_back(g.addNode(0, {rng.unit(), rng.unit()}, round));
        }
        if (round % 50 == 0) checkInvariants(g);
    }
    checkInvariants(g);
    CHECK(g.faceCount() > 0);
}
