// One triangulation of a face in its own plane (face_triangles.hpp), shared
// by the --view page, OBJ's triangles and glTF: the triangles cover the face
// exactly, run its way round, and a face with no area or a crossing outline
// is reported instead of drawn wrong.
#include <catch2/catch.hpp>

#include <cmath>

#include "g2d/face_triangles.hpp"
#include "g2d/graph.hpp"

using namespace g2d;
using namespace g2d::rt;

namespace {

Graph makeGraph() {
    return Graph({KindInfo{ElemClass::Node, false}, KindInfo{ElemClass::Edge, true}, KindInfo{ElemClass::Face, false}});
}

FaceId face(Graph& g, const std::vector<vec3>& corners) {
    std::vector<NodeId> nodes;
    for (const vec3& p : corners) nodes.push_back(g.addNode(0, p, 0));
    return g.addFace(2, nodes, 0);
}

// Area and orientation from the 3D positions, independent of the projection.
vec3 triangleVector(const FaceTriangles& t, const std::array<std::uint32_t, 3>& k) {
    return cross(t.positions[k[1]] - t.positions[k[0]], t.positions[k[2]] - t.positions[k[0]]) / 2.0;
}

double coveredArea(const FaceTriangles& t) {
    double sum = 0;
    for (const auto& k : t.triangles) {
        const vec3 v = triangleVector(t, k);
        CHECK(dot(v, t.normal) > 0);   // each runs the face's way round
        sum += length(v);
    }
    return sum;
}

}  // namespace

TEST_CASE("a non-convex face in a tilted plane is covered exactly, its way round") {
    Graph g = makeGraph();
    // An L of area 3 in the plane x = y (a wall standing diagonally), both ways round.
    const double s = std::sqrt(0.5);
    std::vector<vec3> l;
    for (vec2 p : {vec2(0, 0), vec2(2, 0), vec2(2, 1), vec2(1, 1), vec2(1, 2), vec2(0, 2)}) l.push_back(vec3(p.x * s, p.x * s, p.y));
    for (bool reversed : {false, true}) {
        std::vector<vec3> corners = l;
        if (reversed) std::reverse(corners.begin(), corners.end());
        const FaceTriangles t = triangulateFace(g, face(g, corners));
        REQUIRE(t.problem == FaceShapeProblem::None);
        CHECK(t.triangles.size() == 4);
        CHECK(coveredArea(t) == Approx(3.0).epsilon(1e-12));
        const vec3 expected = reversed ? vec3(-s, s, 0) : vec3(s, -s, 0);
        CHECK(length(t.normal - expected) < 1e-12);
    }
}

TEST_CASE("a face with a corner in the middle of a side keeps it and stays whole") {
    Graph g = makeGraph();
    const FaceTriangles t = triangulateFace(g, face(g, {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}}));
    REQUIRE(t.problem == FaceShapeProblem::None);
    CHECK(coveredArea(t) == Approx(4.0));
    CHECK(t.points.size() == 5);
}

TEST_CASE("a face whose corners lie on one line, or that crosses itself, is reported") {
    Graph g = makeGraph();
    CHECK(triangulateFace(g, face(g, {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}})).problem == FaceShapeProblem::Collinear);
    CHECK(triangulateFace(g, face(g, {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}})).problem == FaceShapeProblem::Collinear);
    // A bow tie: its lobes cancel, the normal is zero.
    CHECK(triangulateFace(g, face(g, {{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}})).problem == FaceShapeProblem::SelfCrossing);
    // Standing upright (in the plane y = 0), seen from no axis it was drawn in.
    CHECK(triangulateFace(g, face(g, {{0, 0, 0}, {1, 0, 1}, {0, 0, 1}, {1, 0, 0}})).problem == FaceShapeProblem::SelfCrossing);
    // A lopsided one: the normal is not zero, the outline still crosses.
    const FaceId bad = face(g, {{0, 0, 0}, {3, 2, 0}, {3, 0, 0}, {0, 1, 0}});
    CHECK(triangulateFace(g, bad).problem == FaceShapeProblem::SelfCrossing);
    CHECK(faceShapeMessage(g, bad, "Wall", FaceShapeProblem::SelfCrossing) ==
          "face " + std::to_string(bad) + " (Wall, corners 14 15 16 17) cannot be drawn as triangles: its outline crosses itself");
}
