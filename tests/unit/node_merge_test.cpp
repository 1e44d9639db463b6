// G^3's Split edge on faces (Graph::insertBetween) and merging of coinciding
// nodes (NodeMerger, §3.1): the thesis's figures as hand-built graphs.
#include <catch2/catch.hpp>

#include <vector>

#include "g2d/graph.hpp"
#include "g2d/node_merge.hpp"
#include "g2d/projection.hpp"

using namespace g2d::rt;

namespace {

// Kinds: 0 node, 1 edge (directed), 2 face.
Graph makeGraph() {
    return Graph({KindInfo{ElemClass::Node, false}, KindInfo{ElemClass::Edge, true}, KindInfo{ElemClass::Face, false}});
}

std::vector<NodeId> corners(const Graph& g, FaceId f) {
    std::vector<NodeId> out;
    CornerId c = g.firstCorner(f);
    for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) out.push_back(g.cornerNode(c));
    return out;
}

std::vector<FaceId> liveFaces(const Graph& g) {
    std::vector<FaceId> out;
    for (FaceId f = 0; f < g.faceCapacity(); ++f)
        if (g.faceAlive(f)) out.push_back(f);
    return out;
}

NodeMerger merger(const Graph& g) {
    return NodeMerger(g, 1e-3, [](Graph& graph, FaceId from, FaceId to) { graph.copyFaceAttrs(from, to); });
}

}  // namespace

TEST_CASE("insert between puts a node into every face on a side, in each face's order", "[g3]") {
    Graph g = makeGraph();
    const NodeId a = g.addNode(0, vec3{0, 0, 0}, 0), b = g.addNode(0, vec3{1, 0, 0}, 0);
    const NodeId c = g.addNode(0, vec3{0, 1, 0}, 0), d = g.addNode(0, vec3{0, -1, 0}, 0);
    const FaceId up = g.addFace(2, std::vector<NodeId>{a, b, c}, 0);     // runs a -> b
    const FaceId down = g.addFace(2, std::vector<NodeId>{b, a, d}, 0);   // runs b -> a
    const FaceId apart = g.addFace(2, std::vector<NodeId>{a, c, d}, 0);  // a and b not a side
    const NodeId m = g.addNode(0, vec3{0.5, 0, 0}, 1);
    CHECK(g.insertBetween(a, b, m) == 2);
    CHECK(corners(g, up) == std::vector<NodeId>{a, m, b, c});
    CHECK(corners(g, down) == std::vector<NodeId>{b, m, a, d});
    CHECK(corners(g, apart) == std::vector<NodeId>{a, c, d});
    CHECK(g.faceCountAt(m) == 2);
    // Again: m is a corner of both already, so nothing changes.
    CHECK(g.insertBetween(a, m, m) == 0);
    CHECK(g.insertBetween(b, a, m) == 0);
}

TEST_CASE("merging: the older node stays at the midpoint with the mean radius", "[g3]") {
    Graph g = makeGraph();
    const NodeId a = g.addNode(0, vec3{0, 0, 1}, 0);
    g.setRadius(a, 0.2);
    const NodeId far = g.addNode(0, vec3{5, 0, 0}, 0);
    NodeMerger mg = merger(g);
    g.forgetChanges();
    const NodeId b = g.addNode(0, vec3{0.0004, 0, 1}, 1);
    g.setRadius(b, 0.4);
    g.addEdge(1, far, b, 1);
    mg.sync(g);
    CHECK(mg.mergeChanged(g, 1e-3) == 1);
    CHECK(!g.nodeAlive(b));
    CHECK(g.nodeCount() == 2);
    CHECK(g.pos3(a) == vec3{0.0002, 0, 1});
    CHECK(g.radius(a) == Approx(0.3));
    REQUIRE(g.edgeCount() == 1);
    CHECK(g.target(0) == a);
}

TEST_CASE("merging Fig 3.3: a triangle whose split side's node lands on its tip is deleted, its doubled sides merged", "[g3]") {
    Graph g = makeGraph();
    const NodeId n0 = g.addNode(0, vec3{0, 0, 0}, 0), n1 = g.addNode(0, vec3{2, 0, 0}, 0), t = g.addNode(0, vec3{1, 1, 0}, 0);
    const EdgeId bottom = g.addEdge(1, n0, n1, 0);
    g.addEdge(1, n1, t, 0);
    g.addEdge(1, t, n0, 0);
    g.addFace(2, std::vector<NodeId>{n0, n1, t}, 0);
    NodeMerger mg = merger(g);
    g.forgetChanges();
    // Split edge on the bottom, its new node placed on the tip.
    const NodeId n2 = g.addNode(0, vec3{1, 1, 0}, 1);
    g.addEdge(1, n0, n2, 1);
    g.reconnectEdge(bottom, n2, n1);
    CHECK(g.insertBetween(n0, n1, n2) == 1);
    mg.sync(g);
    CHECK(mg.mergeChanged(g, 1e-6) == 1);
    CHECK(g.nodeCount() == 3);
    // The split side's halves became (n0, t) and (t, n1), which the triangle
    // had already (reversed): two edges are left, and no side n0 - n1.
    CHECK(g.edgeCount() == 2);
    CHECK(g.faceCount() == 0);   // {n0, t, n1, t}: both parts have two corners
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) CHECK(e <= 2);   // the older edges stayed
}

TEST_CASE("merging splits a face at a node it holds twice and keeps the part with its first corner", "[g3]") {
    Graph g = makeGraph();
    // A hexagon-like ring a b c d e f whose corners b and e come together.
    std::vector<NodeId> n;
    const vec3 at[] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 2, 0}, {0, 2, 0}};
    for (const vec3& p : at) n.push_back(g.addNode(0, p, 0));
    const FaceId ring = g.addFace(2, n, 0);
    NodeMerger mg = merger(g);
    g.forgetChanges();
    g.setPos(n[4], vec3{1, 0, 0});   // e moves onto b (Edit node)
    mg.sync(g);
    CHECK(mg.mergeChanged(g, 1e-6) == 1);
    CHECK(!g.nodeAlive(n[4]));
    const auto faces = liveFaces(g);
    REQUIRE(faces.size() == 2);
    CHECK(faces[0] == ring);
    CHECK(corners(g, ring) == std::vector<NodeId>{n[0], n[1], n[5]});   // a b(=e) f
    CHECK(corners(g, faces[1]) == std::vector<NodeId>{n[1], n[2], n[3]});
    CHECK(g.faceAge(faces[1]) == 0);
}

TEST_CASE("merging removes a face with the same corners as an older one (situation 7)", "[g3]") {
    Graph g = makeGraph();
    const NodeId a = g.addNode(0, vec3{0, 0, 0}, 0), b = g.addNode(0, vec3{1, 0, 0}, 0), c = g.addNode(0, vec3{0, 1, 0}, 0);
    const FaceId first = g.addFace(2, std::vector<NodeId>{a, b, c}, 0);
    NodeMerger mg = merger(g);
    g.forgetChanges();
    const NodeId c2 = g.addNode(0, vec3{0, 1, 0}, 1);
    g.addFace(2, std::vector<NodeId>{c2, b, a}, 1);   // the same triangle, turned the other way
    mg.sync(g);
    CHECK(mg.mergeChanged(g, 1e-6) == 1);
    CHECK(liveFaces(g) == std::vector<FaceId>{first});
}

TEST_CASE("nodes farther apart than the tolerance stay, and unmoved nodes are no candidates", "[g3]") {
    Graph g = makeGraph();
    g.addNode(0, vec3{0, 0, 0}, 0);
    g.addNode(0, vec3{0, 0, 0}, 0);   // coincide, but were there before: not merged
    NodeMerger mg = merger(g);
    g.forgetChanges();
    g.addNode(0, vec3{0.01, 0, 0}, 1);
    mg.sync(g);
    CHECK(mg.mergeChanged(g, 1e-3) == 0);
    CHECK(g.nodeCount() == 3);
}

TEST_CASE("the SVG projection of 3D models: right-handed, z up", "[g3]") {
    const ViewProjection front = viewFrom(vec3{0, -5, 0});
    CHECK(front.right == vec3{1, 0, 0});
    CHECK(front.up == vec3{0, 0, 1});
    CHECK(front.project(vec3{2, 7, 3}) == vec2{2, 3});
    CHECK(front.depth(vec3{0, 1, 0}) > front.depth(vec3{0, -1, 0}));   // +y is farther from a viewer at -y
    const ViewProjection top = viewFrom(vec3{0, 0, 1});
    CHECK(top.project(vec3{2, 7, 3}) == vec2{2, 7});
    CHECK_THROWS_AS(viewFrom(vec3{0, 0, 0}), std::invalid_argument);
}
