// Faces traced from a planar drawing whose edges name the kinds on their
// sides (angle_faces.hpp): kinds, corner order, spikes, holes, pinches,
// and which face each hole (an island's outside) belongs to.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "g2d/angle_faces.hpp"

using namespace g2d::rt;

namespace {

using Corners = std::vector<int>;

double signedArea(const std::vector<vec2>& p, const Corners& c) {
    double a = 0;
    for (size_t i = 0; i < c.size(); ++i) {
        const vec2 u = p[c[i]], v = p[c[(i + 1) % c.size()]];
        a += u.x * v.y - u.y * v.x;
    }
    return a / 2;
}

const std::vector<vec2> kSquare{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

// The unit square counter-clockwise, kind `kind` inside, nothing outside.
std::vector<SidedEdge> squareEdges(int kind) {
    return {{0, 1, kind, -1}, {1, 2, kind, -1}, {2, 3, kind, -1}, {3, 0, kind, -1}};
}

}  // namespace

TEST_CASE("a unit square gives one counter-clockwise face", "[angle-faces]") {
    const auto faces = traceFaces(kSquare, squareEdges(0));
    REQUIRE(faces.size() == 1);
    CHECK(faces[0].kind == 0);
    CHECK(faces[0].corners == Corners{0, 1, 2, 3});
    CHECK(signedArea(kSquare, faces[0].corners) == 1.0);
}

TEST_CASE("edge directions do not matter when left and right follow them", "[angle-faces]") {
    const std::vector<SidedEdge> edges{{0, 1, 0, -1}, {2, 1, -1, 0}, {2, 3, 0, -1}, {0, 3, -1, 0}};
    const auto faces = traceFaces(kSquare, edges);
    REQUIRE(faces.size() == 1);
    CHECK(faces[0].kind == 0);
    CHECK(faces[0].corners == Corners{0, 1, 2, 3});
}

TEST_CASE("two squares sharing a side keep their own kinds", "[angle-faces]") {
    const std::vector<vec2> p{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}};
    const std::vector<SidedEdge> edges{{0, 1, 0, -1}, {1, 4, 0, 1},  {4, 5, 0, -1}, {5, 0, 0, -1},
                                       {1, 2, 1, -1}, {2, 3, 1, -1}, {3, 4, 1, -1}};
    const auto faces = traceFaces(p, edges);
    REQUIRE(faces.size() == 2);
    CHECK(faces[0].kind == 0);
    CHECK(faces[0].corners == Corners{0, 1, 4, 5});
    // Its least half-edge is 4->1 (edge 1 backwards): the corners start at 4.
    CHECK(faces[1].kind == 1);
    CHECK(faces[1].corners == Corners{4, 1, 2, 3});
}

TEST_CASE("a dangling path inside a square is cut away", "[angle-faces]") {
    std::vector<vec2> p = kSquare;
    p.push_back({0.5, 0.5});
    p.push_back({0.5, 0.8});
    // The path comes first, so the walk starts on it and the square is cut
    // out of it starting at 1: the corners must still start at 0 (0->1 is
    // the square's least half-edge).
    std::vector<SidedEdge> edges{{1, 4, 0, 0}, {4, 5, 0, 0}};
    for (const SidedEdge& e : squareEdges(0)) edges.push_back(e);
    const auto faces = traceFaces(p, edges);
    REQUIRE(faces.size() == 1);
    CHECK(faces[0].kind == 0);
    CHECK(faces[0].corners == Corners{0, 1, 2, 3});
}

TEST_CASE("a square with no kind on either side is no face", "[angle-faces]") {
    CHECK(traceFaces(kSquare, squareEdges(-1)).empty());
}

TEST_CASE("a triangle hole is its own face and its outside is not", "[angle-faces]") {
    const std::vector<vec2> p{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {2, 3}};
    auto edges = squareEdges(0);
    edges.push_back({4, 5, 1, 0});
    edges.push_back({5, 6, 1, 0});
    edges.push_back({6, 4, 1, 0});
    const auto faces = traceFaces(p, edges);
    REQUIRE(faces.size() == 2);
    CHECK(faces[0].kind == 0);
    CHECK(faces[0].corners == Corners{0, 1, 2, 3});
    // The triangle's outside, clockwise from its least half-edge (5->4), is
    // the square's hole.
    CHECK(faces[0].holes == std::vector<Corners>{{5, 4, 6}});
    CHECK(faces[1].kind == 1);
    CHECK(faces[1].corners == Corners{4, 5, 6});
    CHECK(faces[1].holes.empty());
}

TEST_CASE("a bridge to a triangle hole is cut away", "[angle-faces]") {
    const std::vector<vec2> p{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {2, 3}};
    auto edges = squareEdges(0);
    edges.push_back({4, 5, 1, 0});
    edges.push_back({5, 6, 1, 0});
    edges.push_back({6, 4, 1, 0});
    edges.push_back({2, 6, 0, 0});   // from a corner the square's walk passes mid-way
    const auto faces = traceFaces(p, edges);
    REQUIRE(faces.size() == 2);
    CHECK(faces[0].corners == Corners{0, 1, 2, 3});
    CHECK(faces[0].holes == std::vector<Corners>{{5, 4, 6}});   // cut off the square's walk
    CHECK(faces[1].corners == Corners{4, 5, 6});
}

namespace {

// A square of side `side` from `at`, counter-clockwise, `inside` on its left
// and `outside` on its right; its corners appended to `p`.
void addSquare(std::vector<vec2>& p, std::vector<SidedEdge>& edges, vec2 at, double side, int inside, int outside) {
    const int v = static_cast<int>(p.size());
    p.insert(p.end(), {at, {at.x + side, at.y}, {at.x + side, at.y + side}, {at.x, at.y + side}});
    for (int i = 0; i < 4; ++i) edges.push_back({v + i, v + (i + 1) % 4, inside, outside});
}

}  // namespace

TEST_CASE("islands are holes of the innermost face around them, each clockwise", "[angle-faces]") {
    // A 10-square (kind 0) holding two islands: a 2-square (kind 1) and a
    // 4-square (kind 2) that holds a 1-square (kind 3); a 1-square outside all.
    std::vector<vec2> p;
    std::vector<SidedEdge> edges;
    addSquare(p, edges, {0, 0}, 10, 0, -1);   // corners 0-3
    addSquare(p, edges, {1, 1}, 2, 1, 0);     // 4-7
    addSquare(p, edges, {5, 5}, 4, 2, 0);     // 8-11
    addSquare(p, edges, {6, 6}, 1, 3, 2);     // 12-15
    addSquare(p, edges, {20, 0}, 1, 4, -1);   // 16-19
    const auto faces = traceFaces(p, edges);
    REQUIRE(faces.size() == 5);
    CHECK(faces[0].holes == std::vector<Corners>{{5, 4, 7, 6}, {9, 8, 11, 10}});
    CHECK(faces[1].holes.empty());
    CHECK(faces[2].holes == std::vector<Corners>{{13, 12, 15, 14}});
    CHECK(faces[3].holes.empty());
    CHECK(faces[4].holes.empty());
    for (const TracedFace& f : faces)
        for (const Corners& hole : f.holes) CHECK(signedArea(p, hole) < 0);
}

TEST_CASE("an island in a region that is no face is no hole", "[angle-faces]") {
    // A frame: an outer square whose inside has no kind, but for a ring of
    // kind 0 around an inner square with no kind; an island in the middle.
    std::vector<vec2> p;
    std::vector<SidedEdge> edges;
    addSquare(p, edges, {0, 0}, 10, 0, -1);
    addSquare(p, edges, {2, 2}, 6, -1, 0);    // the frame's inner side: no kind inside
    addSquare(p, edges, {4, 4}, 2, 1, -1);    // in the unkinded middle
    const auto faces = traceFaces(p, edges);
    REQUIRE(faces.size() == 2);
    CHECK(faces[0].kind == 0);
    CHECK(faces[0].holes == std::vector<Corners>{{5, 4, 7, 6}});   // the middle, not the island
    CHECK(faces[1].kind == 1);
    CHECK(faces[1].holes.empty());
}

TEST_CASE("a hole touching its face at a corner is cut off the walk", "[angle-faces]") {
    // A triangle inside a square, sharing the square's corner 2.
    const std::vector<vec2> p{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 3}, {3, 2}};
    auto edges = squareEdges(0);
    edges.push_back({2, 4, 1, 0});   // counter-clockwise round the triangle
    edges.push_back({4, 5, 1, 0});
    edges.push_back({5, 2, 1, 0});
    const auto faces = traceFaces(p, edges);
    REQUIRE(faces.size() == 2);
    CHECK(faces[0].corners == Corners{0, 1, 2, 3});
    REQUIRE(faces[0].holes.size() == 1);
    CHECK(signedArea(p, faces[0].holes[0]) == -1.5);
    CHECK(faces[1].kind == 1);
}

TEST_CASE("faces come in the order of their least half-edge", "[angle-faces]") {
    // Square A (kind 0) with a spike, listed around one edge of square B
    // (kind 1): the walk through A starts first (on the spike), yet B's
    // least half-edge (2) is below A's (4).
    std::vector<vec2> p = kSquare;
    p.insert(p.end(), {{0.5, 0.5}, {2, 0}, {3, 0}, {3, 1}, {2, 1}});
    std::vector<SidedEdge> edges{{0, 4, 0, 0}, {5, 6, 1, -1}};
    for (const SidedEdge& e : squareEdges(0)) edges.push_back(e);
    edges.insert(edges.end(), {{6, 7, 1, -1}, {7, 8, 1, -1}, {8, 5, 1, -1}});
    const auto faces = traceFaces(p, edges);
    REQUIRE(faces.size() == 2);
    CHECK(faces[0].kind == 1);
    CHECK(faces[0].corners == Corners{5, 6, 7, 8});
    CHECK(faces[1].kind == 0);
    CHECK(faces[1].corners == Corners{0, 1, 2, 3});
}

TEST_CASE("a figure-eight gives two triangles", "[angle-faces]") {
    const std::vector<vec2> p{{0, 0}, {2, 0}, {1, 1}, {-2, 0}, {-1, -1}};
    const std::vector<SidedEdge> edges{{0, 1, 0, -1}, {1, 2, 0, -1}, {2, 0, 0, -1},
                                       {0, 3, 1, -1}, {3, 4, 1, -1}, {4, 0, 1, -1}};
    const auto faces = traceFaces(p, edges);
    REQUIRE(faces.size() == 2);
    CHECK(faces[0].kind == 0);
    CHECK(faces[0].corners == Corners{0, 1, 2});
    CHECK(faces[1].kind == 1);
    CHECK(faces[1].corners == Corners{0, 3, 4});
}

TEST_CASE("disagreeing sides take the most common kind, ties the smallest", "[angle-faces]") {
    auto edges = squareEdges(2);
    edges[3].left = 5;
    auto faces = traceFaces(kSquare, edges);
    REQUIRE(faces.size() == 1);
    CHECK(faces[0].kind == 2);
    edges = squareEdges(3);
    edges[0].left = edges[2].left = 1;
    faces = traceFaces(kSquare, edges);
    REQUIRE(faces.size() == 1);
    CHECK(faces[0].kind == 1);
}

TEST_CASE("empty input gives no faces", "[angle-faces]") {
    CHECK(traceFaces({}, {}).empty());
    CHECK(traceFaces(kSquare, {}).empty());
}

TEST_CASE("bad edges are ignored", "[angle-faces]") {
    std::vector<vec2> p = kSquare;
    p.push_back({std::numeric_limits<double>::quiet_NaN(), 0.5});
    auto edges = squareEdges(0);
    edges.push_back({-1, 2, 0, 0});
    edges.push_back({0, 9, 0, 0});
    edges.push_back({1, 1, 0, 0});
    edges.push_back({0, 4, 0, 0});
    edges.push_back({4, 2, 0, 0});
    const auto faces = traceFaces(p, edges);
    REQUIRE(faces.size() == 1);
    CHECK(faces[0].corners == Corners{0, 1, 2, 3});
    CHECK(traceFaces({}, squareEdges(0)).empty());
}
