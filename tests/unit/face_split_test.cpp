// G^3's Split face on one face (face_split.hpp): the fan, the cut between
// two chosen corners (§3.4, Fig. 3.16), and the cases that leave it alone.
#include <catch2/catch.hpp>

#include <vector>

#include "g2d/face_split.hpp"

using namespace g2d::rt;

namespace {

// Kinds: 0 node, 1 edge, 2 face (with one attribute in the graph's pool).
struct Quad {
    Graph g{{KindInfo{ElemClass::Node, false}, KindInfo{ElemClass::Edge, true}, KindInfo{ElemClass::Face, false}}};
    std::vector<NodeId> n;
    FaceId f = kNoId;
    Quad() {
        g.setKindDefaults(2, {Value{7LL}});
        for (vec3 p : {vec3{0, 0, 0}, vec3{2, 0, 0}, vec3{2, 2, 0}, vec3{0, 2, 0}}) n.push_back(g.addNode(0, p, 0));
        f = g.addFace(2, n, 0);
        g.setFaceAttr(f, 0, Value{42LL});
    }
    SplitMakers makers(bool centre = true) {
        SplitMakers m;
        if (centre) m.centre = [this] { return g.addNode(0, vec3{1, 1, 0}, 1); };
        m.edge = [this](NodeId a, NodeId b) { return g.addEdge(1, a, b, 1); };
        m.copyFace = [this](FaceId from, FaceId to) { g.copyFaceAttrs(from, to); };
        return m;
    }
    FaceSplit split(std::vector<std::uint8_t> chosen, bool centre = true) {
        std::vector<NodeId> picked;
        for (std::size_t i = 0; i < chosen.size(); ++i)
            if (chosen[i]) picked.push_back(n[i]);
        return splitFace(g, f, picked, makers(centre), 1);
    }
    std::vector<NodeId> corners(FaceId face) const {
        std::vector<NodeId> out;
        CornerId c = g.firstCorner(face);
        for (int i = 0; i < g.cornerCount(face); ++i, c = g.nextCorner(c)) out.push_back(g.cornerNode(c));
        return out;
    }
};

}  // namespace

TEST_CASE("split face with every corner chosen: a fan around the new node, the face's way round", "[g3][split]") {
    Quad q;
    const FaceSplit s = q.split({1, 1, 1, 1});
    REQUIRE(s.centre != kNoId);
    CHECK(q.g.pos3(s.centre) == vec3{1, 1, 0});
    CHECK(s.edges.size() == 4);
    for (std::size_t i = 0; i < 4; ++i) {
        CHECK(q.g.source(s.edges[i]) == q.n[i]);
        CHECK(q.g.target(s.edges[i]) == s.centre);
    }
    REQUIRE(s.faces.size() == 4);
    for (std::size_t i = 0; i < 4; ++i) {
        CHECK(q.corners(s.faces[i]) == std::vector<NodeId>{q.n[i], q.n[(i + 1) % 4], s.centre});
        CHECK(q.g.signedArea(s.faces[i]) > 0);                // counter-clockwise, as the quad
        CHECK(q.g.faceAttr(s.faces[i], 0) == Value{42LL});     // the quad's attributes
        CHECK(q.g.faceAge(s.faces[i]) == 1);
    }
    CHECK(!q.g.faceAlive(q.f));
}

TEST_CASE("split face with three of four corners chosen: faces between consecutive chosen corners", "[g3][split]") {
    Quad q;
    const FaceSplit s = q.split({1, 1, 0, 1});
    REQUIRE(s.faces.size() == 3);
    CHECK(q.corners(s.faces[0]) == std::vector<NodeId>{q.n[0], q.n[1], s.centre});
    CHECK(q.corners(s.faces[1]) == std::vector<NodeId>{q.n[1], q.n[2], q.n[3], s.centre});
    CHECK(q.corners(s.faces[2]) == std::vector<NodeId>{q.n[3], q.n[0], s.centre});
    CHECK(s.edges.size() == 3);
}

TEST_CASE("split face with two opposite corners chosen: one edge, two faces, no node (§3.4)", "[g3][split]") {
    Quad q;
    const std::size_t nodes = q.g.nodeCount();
    const FaceSplit s = q.split({0, 1, 0, 1});
    CHECK(s.centre == kNoId);
    CHECK(q.g.nodeCount() == nodes);
    REQUIRE(s.edges.size() == 1);
    CHECK(q.g.source(s.edges[0]) == q.n[1]);
    CHECK(q.g.target(s.edges[0]) == q.n[3]);
    REQUIRE(s.faces.size() == 2);
    CHECK(q.corners(s.faces[0]) == std::vector<NodeId>{q.n[1], q.n[2], q.n[3]});
    CHECK(q.corners(s.faces[1]) == std::vector<NodeId>{q.n[3], q.n[0], q.n[1]});
    CHECK(!q.g.faceAlive(q.f));
}

TEST_CASE("split face leaves the face alone with fewer than two chosen corners, or two neighbours", "[g3][split]") {
    for (const std::vector<std::uint8_t>& chosen :
         {std::vector<std::uint8_t>{0, 0, 0, 0}, {0, 0, 1, 0}, {1, 1, 0, 0}, {1, 0, 0, 1}}) {
        Quad q;
        const FaceSplit s = q.split(chosen);
        CHECK(s.faces.empty());
        CHECK(s.edges.empty());
        CHECK(s.centre == kNoId);
        CHECK(q.g.faceAlive(q.f));
        CHECK(q.g.faceCount() == 1);
        CHECK(q.g.edgeCount() == 0);
    }
}

TEST_CASE("split face without a centre maker cuts only by a chord", "[g3][split]") {
    Quad q;
    CHECK(q.split({1, 1, 1, 1}, false).faces.empty());
    CHECK(q.g.faceAlive(q.f));
    CHECK(q.split({1, 0, 1, 0}, false).faces.size() == 2);
}

TEST_CASE("split face reads the face's corners as they are now: a corner inserted since is not chosen", "[g3][split]") {
    Quad q;
    const NodeId m = q.g.addNode(0, vec3{1, -1, 0}, 1);
    q.g.insertBetween(q.n[0], q.n[1], m);
    // Chosen before the insert: all four old corners (a fan of four, m on the first part).
    const FaceSplit s = q.split({1, 1, 1, 1});
    REQUIRE(s.faces.size() == 4);
    CHECK(q.corners(s.faces[0]) == std::vector<NodeId>{q.n[0], m, q.n[1], s.centre});
}
