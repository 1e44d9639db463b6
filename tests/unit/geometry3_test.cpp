// The G^3 geometry kernel (runtime/engine/internal/g2d/geometry3.hpp): every branch
// of the intersection tests on hand-built cases with exact answers, the same
// answers scaled and moved, triangulations checked triangle by triangle,
// areas and normals.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "g2d/geometry3.hpp"

using namespace g2d::rt;
using Tris = std::vector<std::array<int, 3>>;

namespace {

// The unit right triangle in z = 0, counter-clockwise seen from +z.
const vec3 P0(0, 0, 0), P1(1, 0, 0), P2(0, 1, 0);

// Each case is checked as given and after p -> p * k + offset: the
// tolerance is relative, so the answers must not change.
void eachFrame(const std::function<void(const std::function<vec3(vec3)>&)>& check) {
    for (double k : {1.0, 1e-6, 1e6}) {
        const vec3 offset = vec3(3, -7, 11) * (10 * k);
        check([&](vec3 p) { return p * k + offset; });
    }
}

}  // namespace

TEST_CASE("segment/segment: crossing, touching, apart, parallel, collinear, skew", "[geometry3]") {
    const vec3 a0(0, 0, 0), a1(2, 0, 0);
    struct Case {
        vec3 b0, b1;
        double distance;
    };
    const Case cases[] = {
        {{1, -1, 0}, {1, 1, 0}, 0},                 // crossing
        {{1, 0, 0}, {1, 1, 0}, 0},                  // touching: T-junction
        {{2, 0, 0}, {3, 1, 0}, 0},                  // touching: end to end
        {{3, -1, 0}, {3, 1, 0}, 1},                 // coplanar, apart beyond a's end
        {{0, 1, 0}, {2, 1, 0}, 1},                  // parallel, side by side
        {{3, 1, 0}, {5, 1, 0}, std::sqrt(2.0)},     // parallel, offset along the line
        {{1, 0, 0}, {3, 0, 0}, 0},                  // collinear, overlapping
        {{4, 0, 0}, {3, 0, 0}, 1},                  // collinear, disjoint (reversed)
        {{1, -1, 0.5}, {1, 1, 0.5}, 0.5},           // skew, closest points inside both
        {{3, -1, 0.5}, {3, 1, 0.5}, std::sqrt(1.25)},  // skew, closest line points beyond a's end
        {{1, 1, 1}, {1, 1, 1}, std::sqrt(2.0)},     // b is a point
    };
    eachFrame([&](const auto& f) {
        const double k = glm::length(f(vec3(1, 0, 0)) - f(vec3(0)));
        for (const Case& c : cases) {
            CAPTURE(c.b0.x, c.b0.y, c.b0.z, c.b1.x, c.b1.y, c.b1.z, k);
            CHECK(segmentDistance(f(a0), f(a1), f(c.b0), f(c.b1)) == Approx(c.distance * k).margin(1e-9 * k));
            CHECK(segmentsIntersect(f(a0), f(a1), f(c.b0), f(c.b1), 0) == (c.distance == 0));
            // Closed: at exactly the thickness they still intersect; just below, not.
            if (c.distance > 0) {
                CHECK(segmentsIntersect(f(a0), f(a1), f(c.b0), f(c.b1), c.distance * k));
                CHECK_FALSE(segmentsIntersect(f(a0), f(a1), f(c.b0), f(c.b1), c.distance * k * 0.999));
            }
            // Symmetric in the two segments and their directions.
            CHECK(segmentDistance(f(c.b1), f(c.b0), f(a1), f(a0)) == Approx(c.distance * k).margin(1e-9 * k));
        }
    });
}

TEST_CASE("segment/segment: the axis distance, where the thesis's parameter test differs", "[geometry3]") {
    // Closest line points beyond a's end: the thesis's s <= l + h (3 <= 3.1)
    // with line distance 0.5 <= h would call this an intersection; the axes
    // are sqrt(1.25) ~ 1.118 > 1.1 apart.
    CHECK_FALSE(segmentsIntersect({0, 0, 0}, {2, 0, 0}, {3, -1, 0.5}, {3, 1, 0.5}, 1.1));
    // Nearly parallel, side by side 0.1 apart: the lines meet far beyond both
    // ends, so the thesis's parameter test misses them.
    const vec3 b0(0, 0.1, 0), b1(10, 0.1 + 1e-6, 0);
    CHECK(segmentDistance({0, 0, 0}, {10, 0, 0}, b0, b1) == Approx(0.1));
    CHECK(segmentsIntersect({0, 0, 0}, {10, 0, 0}, b0, b1, 0.2));
    CHECK_FALSE(segmentsIntersect({0, 0, 0}, {10, 0, 0}, b0, b1, 0.05));
}

TEST_CASE("segment distance agrees with dense sampling on random segments", "[geometry3]") {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> u(-1, 1);
    const auto point = [&] { return vec3(u(rng), u(rng), u(rng)); };
    constexpr int kSteps = 200;
    for (int round = 0; round < 300; ++round) {
        const vec3 a0 = point(), a1 = round % 10 == 0 ? a0 + vec3(0.3, 0, 0) : point();
        // Every tenth pair parallel; some share an end.
        const vec3 b0 = round % 7 == 0 ? a1 : point();
        const vec3 b1 = round % 10 == 0 ? b0 + vec3(-0.5, 0, 0) : point();
        double sampled = 1e9;
        for (int i = 0; i <= kSteps; ++i)
            for (int j = 0; j <= kSteps; ++j) {
                const vec3 p = a0 + (a1 - a0) * (double(i) / kSteps), q = b0 + (b1 - b0) * (double(j) / kSteps);
                sampled = std::min(sampled, glm::length(p - q));
            }
        const double d = segmentDistance(a0, a1, b0, b1);
        CAPTURE(round);
        CHECK(d <= sampled + 1e-12);
        CHECK(d >= sampled - (glm::length(a1 - a0) + glm::length(b1 - b0)) / kSteps);
    }
}

TEST_CASE("edges sharing a node: contact at the node is ignored", "[geometry3]") {
    const vec3 n(0, 0, 0);
    eachFrame([&](const auto& f) {
        const double k = glm::length(f(vec3(1, 0, 0)) - f(vec3(0)));
        // Perpendicular: always touching at n (plain test), not an intersection here.
        CHECK(segmentsIntersect(f(n), f({1, 0, 0}), f(n), f({0, 1, 0}), 0));
        CHECK_FALSE(segmentsIntersectSharing(f(n), f({1, 0, 0}), f({0, 1, 0}), 0));
        CHECK_FALSE(segmentsIntersectSharing(f(n), f({1, 0, 0}), f({0, 1, 0}), 0.5 * k));
        // ... unless the thickness buries one whole edge in the other.
        CHECK(segmentsIntersectSharing(f(n), f({1, 0, 0}), f({0, 1, 0}), 1.0 * k));
        // Straight on (a branch continuing its parent): never.
        CHECK_FALSE(segmentsIntersectSharing(f(n), f({1, 0, 0}), f({-1, 0, 0}), 0));
        CHECK_FALSE(segmentsIntersectSharing(f(n), f({1, 0, 0}), f({-1, 0, 0}), 0.5 * k));
        // Collinear and overlapping beyond the node: always.
        CHECK(segmentsIntersectSharing(f(n), f({2, 0, 0}), f({1, 0, 0}), 0));
        // Folded back along its neighbour: within the thickness, it intersects.
        CHECK(segmentsIntersectSharing(f(n), f({2, 0, 0}), f({2, 0.1, 0}), 0.15 * k));
        CHECK_FALSE(segmentsIntersectSharing(f(n), f({2, 0, 0}), f({2, 0.1, 0}), 0.05 * k));
        CHECK_FALSE(segmentsIntersectSharing(f(n), f({2, 0, 0}), f({2, 0.1, 0}), 0));
    });
}

TEST_CASE("edge thickness: the sum of the two edges' mean end radii", "[geometry3]") {
    CHECK(edgeThickness(1, 3, 0.5, 0.5) == 2.5);
    CHECK(edgeThickness(0, 0, 0, 0) == 0);
}

TEST_CASE("segment/triangle: through, past, touching, parallel, coplanar", "[geometry3]") {
    struct Case {
        vec3 o0, o1;
        bool hit;
    };
    const Case cases[] = {
        {{0.25, 0.25, -1}, {0.25, 0.25, 1}, true},   // through the interior
        {{0.25, 0.25, 1}, {0.1, 0.2, -2}, true},     // slanted, through the interior
        {{0.75, 0.75, -1}, {0.75, 0.75, 1}, false},  // past the long side
        {{-0.1, 0.5, -1}, {-0.1, 0.5, 1}, false},    // past a short side
        {{0.5, 0.5, -1}, {0.5, 0.5, 1}, false},      // through a side: touching
        {{0, 0.5, -1}, {0, 0.5, 1}, false},          // ... each side
        {{0.5, 0, 1}, {0.5, 0, -1}, false},
        {{0, 0, -1}, {0, 0, 1}, false},              // through a vertex: touching
        {{0.25, 0.25, 0}, {0.25, 0.25, 1}, false},   // an end on the face: touching
        {{0.25, 0.25, 0.5}, {0.25, 0.25, 1}, false}, // short of the face
        {{0.25, 0.25, -1}, {0.25, 0.25, -0.5}, false},
        {{-1, 0.25, 1}, {2, 0.25, 1}, false},        // parallel to the plane, off it
        // Coplanar (§3.2.2's 2D case):
        {{-1, 0.25, 0}, {2, 0.25, 0}, true},         // crossing the triangle
        {{0.1, 0.1, 0}, {0.2, 0.2, 0}, true},        // wholly inside
        {{0.2, 0.2, 0}, {2, 2, 0}, true},            // from inside out
        {{0, 0, 0}, {0.3, 0.3, 0}, true},            // from a vertex into the interior
        {{0, 0, 0}, {-1, -1, 0}, false},             // from a vertex outwards
        {{-1, 2, 0}, {2, 2, 0}, false},              // the triangle on one side of its line
        {{2, 0.25, 0}, {3, 0.25, 0}, false},         // on a crossing line, both ends beyond a side
        {{0, 0, 0}, {1, 0, 0}, false},               // along a side
        {{-1, 0, 0}, {2, 0, 0}, false},              // along a side, beyond both ends
        {{0.5, 0, 0}, {0.5, -1, 0}, false},          // from a side outwards
        {{-1, 1, 0}, {1, -1, 0}, false},             // through a vertex, the triangle on one side
        {{-1, 2, 0}, {2, -1, 0}, false},             // the long side's line, past it
    };
    eachFrame([&](const auto& f) {
        for (const Case& c : cases) {
            CAPTURE(c.o0.x, c.o0.y, c.o0.z, c.o1.x, c.o1.y, c.o1.z);
            CHECK(segmentTriangle(f(c.o0), f(c.o1), f(P0), f(P1), f(P2)) == c.hit);
            // The same answer for the segment reversed and the triangle turned.
            CHECK(segmentTriangle(f(c.o1), f(c.o0), f(P1), f(P2), f(P0)) == c.hit);
            CHECK(segmentTriangle(f(c.o0), f(c.o1), f(P2), f(P1), f(P0)) == c.hit);
        }
    });
    // No interior, no intersection: a degenerate triangle or segment.
    CHECK_FALSE(segmentTriangle({1, -1, 0}, {1, 1, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}));
    CHECK_FALSE(segmentTriangle({0.25, 0.25, 0}, {0.25, 0.25, 0}, P0, P1, P2));
}

TEST_CASE("triangle/triangle: piercing, apart, coplanar overlap, shared vertex or side", "[geometry3]") {
    struct Case {
        vec3 q0, q1, q2;
        bool hit;
    };
    const Case cases[] = {
        {{0.2, 0.2, -1}, {0.2, 0.2, 1}, {-1, -1, 0}, true},   // an edge pierces the interior
        {{-1, 0.3, -1}, {2, 0.3, -1}, {0.3, 0.3, 1}, true},   // a chord crosses, no vertex inside
        {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, false},             // parallel above
        {{2, 2, -1}, {2, 2, 1}, {3, 3, 0}, false},            // apart
        {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, false},             // a shared side, upright
        {{1, 0, 0}, {0, 0, 0}, {0.3, -0.2, 0.5}, false},      // a shared side, tilted
        {{0, 0, 0}, {-1, 0, 1}, {0, -1, 1}, false},           // a shared vertex
        {{0, 0, 0}, {1, 1, 1}, {1, 1, -1}, true},             // a shared vertex, then through
        {{1, 0, 0}, {0, 1, 0}, {1, 1, 0}, false},             // coplanar, a shared side (flat mesh)
        {{1, 0, 0}, {2, 0, 0}, {1, -1, 0}, false},            // coplanar, a shared vertex
        {{0, 0, 0}, {1, 0, 0}, {0.2, 0.2, 0}, true},          // coplanar, folded onto it
        {{0.2, 0.2, 0}, {2, 0.2, 0}, {0.2, 2, 0}, true},      // coplanar, overlapping
        {{0.1, 0.1, 0}, {0.3, 0.1, 0}, {0.1, 0.3, 0}, true},  // coplanar, inside
        {{-0.5, -0.5, 0}, {3, -0.5, 0}, {-0.5, 3, 0}, true},  // coplanar, around it
        {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, true},              // the same triangle
        {{0, 1, 0}, {1, 0, 0}, {0, 0, 0}, true},              // the same, reversed
        {{2, 0, 0}, {3, 0, 0}, {2, 1, 0}, false},             // coplanar, apart
    };
    eachFrame([&](const auto& f) {
        for (const Case& c : cases) {
            CAPTURE(c.q0.x, c.q0.y, c.q0.z, c.q1.x, c.q1.y, c.q1.z, c.q2.x, c.q2.y, c.q2.z);
            CHECK(trianglesIntersect(f(P0), f(P1), f(P2), f(c.q0), f(c.q1), f(c.q2)) == c.hit);
            CHECK(trianglesIntersect(f(c.q0), f(c.q1), f(c.q2), f(P0), f(P1), f(P2)) == c.hit);
        }
    });
}

TEST_CASE("triangulate: small and convex polygons", "[geometry3]") {
    const std::vector<vec3> tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK(triangulate(tri) == Tris{{0, 1, 2}});
    CHECK(triangulate(std::span(tri).first(2)).empty());
    // A square: both diagonals are as short; the lower pair (0, 2) wins.
    const std::vector<vec3> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    CHECK(triangulate(square) == Tris{{0, 1, 2}, {0, 2, 3}});
    // A convex pentagon: the shortest diagonal (1, 3) first, then (0, 3)
    // before (1, 4) (both length^2 8.5).
    const std::vector<vec3> pentagon{{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1.5, 2.5, 0}, {-0.5, 1.5, 0}};
    CHECK(triangulate(pentagon) == Tris{{0, 1, 3}, {0, 3, 4}, {1, 2, 3}});
}

TEST_CASE("triangulate: concave polygons", "[geometry3]") {
    // An L: (2, 4) is as short as the diagonals kept but lies outside.
    const std::vector<vec3> ell{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    CHECK(triangulate(ell) == Tris{{0, 1, 3}, {0, 3, 5}, {1, 2, 3}, {3, 4, 5}});
    CHECK(polygonArea3(ell) == Approx(3));
    // A comb of two teeth: (3, 6) is shortest but spans the gap between the
    // teeth, (2, 6) and (3, 7) run through a vertex, (3, 5) and (4, 6) lie in
    // the gap.
    const std::vector<vec3> comb{{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {2, 2, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    CHECK(triangulate(comb) == Tris{{0, 1, 4}, {0, 4, 5}, {0, 5, 7}, {1, 2, 4}, {2, 3, 4}, {5, 6, 7}});
    CHECK(polygonArea3(comb) == Approx(5));
    // The same, clockwise: the same triangles (each in the polygon's order).
    std::vector<vec3> flipped = comb;
    for (vec3& p : flipped) p.y = -p.y;
    CHECK(triangulate(flipped) == triangulate(comb));
}

TEST_CASE("triangulate: a comb of many teeth covers it exactly", "[geometry3]") {
    // Teeth [2i, 2i+1] x [1, 2] on a base [0, 2t-1] x [0, 1], tilted out of
    // the axis planes.
    const int teeth = 6;
    std::vector<vec3> outline{{0, 0, 0}, {2.0 * teeth - 1, 0, 0}};
    for (int i = teeth - 1; i >= 0; --i) {
        outline.emplace_back(2.0 * i + 1, 2, 0);
        outline.emplace_back(2.0 * i, 2, 0);
        if (i > 0) {
            outline.emplace_back(2.0 * i, 1, 0);
            outline.emplace_back(2.0 * i - 1, 1, 0);
        }
    }
    // Rotate in 3D: x-axis by 30 degrees, then z by 20.
    const double a = 0.5235987755982988, b = 0.3490658503988659;
    for (vec3& p : outline) {
        p = {p.x, p.y * std::cos(a) - p.z * std::sin(a), p.y * std::sin(a) + p.z * std::cos(a)};
        p = {p.x * std::cos(b) - p.y * std::sin(b), p.x * std::sin(b) + p.y * std::cos(b), p.z};
    }
    const auto tris = triangulate(outline);
    REQUIRE(tris.size() == outline.size() - 2);
    CHECK(polygonArea3(outline) == Approx(2.0 * teeth - 1 + teeth));
    // Not the fan: vertex 0 cannot see the far teeth.
    Tris fan;
    for (int i = 1; i + 1 < static_cast<int>(outline.size()); ++i) fan.push_back({0, i, i + 1});
    CHECK(tris != fan);
    const vec3 n = polygonNormal(outline);
    for (const auto& t : tris) {
        CHECK(t[0] < t[1]);
        CHECK(t[1] < t[2]);
        // Each turns the polygon's way: none is folded over.
        CHECK(glm::dot(glm::cross(outline[t[1]] - outline[t[0]], outline[t[2]] - outline[t[0]]), n) > 0);
    }
}

TEST_CASE("triangulate: a vertex on the line between its neighbours", "[geometry3]") {
    // (0, 2) is the shortest diagonal but runs through vertex 1: no
    // zero-area triangle {0, 1, 2}.
    const std::vector<vec3> poly{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    CHECK(triangulate(poly) == Tris{{0, 1, 4}, {1, 2, 3}, {1, 3, 4}});
    CHECK(polygonArea3(poly) == Approx(4));
}

TEST_CASE("triangulate: non-planar quads split along the shorter diagonal", "[geometry3]") {
    // Diagonal (1, 3) has length^2 5, (0, 2) has 6.
    const std::vector<vec3> quad{{0, 0, 0}, {2, 0, 0}, {2, 1, 1}, {0, 1, 0}};
    CHECK(triangulate(quad) == Tris{{0, 1, 3}, {1, 2, 3}});
    CHECK(polygonArea3(quad) == Approx(2.5));  // the other diagonal gives sqrt(2) + sqrt(5)/2
    // Listed from another node: the same diagonal, so the same area.
    const std::vector<vec3> rotated{quad[1], quad[2], quad[3], quad[0]};
    CHECK(triangulate(rotated) == Tris{{0, 1, 2}, {0, 2, 3}});
    CHECK(polygonArea3(rotated) == Approx(2.5));
    // A saddle with equal diagonals: the lower pair (0, 2).
    const std::vector<vec3> saddle{{0, 0, 0}, {1, 0, 1}, {1, 1, 0}, {0, 1, 1}};
    CHECK(triangulate(saddle) == Tris{{0, 1, 2}, {0, 2, 3}});
    CHECK(polygonArea3(saddle) == Approx(std::sqrt(3.0)));
}

TEST_CASE("triangulate: the 2D view of a wall lower than it is wide", "[geometry3]") {
    // An L in the plane x = y, 4 wide (5.66 along the wall) and 2 high:
    // dropping the AABB's smallest extent (z) would flatten it to a line.
    const std::vector<vec3> wall{{0, 0, 0}, {4, 4, 0}, {4, 4, 1}, {2, 2, 1}, {2, 2, 2}, {0, 0, 2}};
    CHECK(triangulate(wall) == Tris{{0, 1, 3}, {0, 3, 5}, {1, 2, 3}, {3, 4, 5}});
    CHECK(polygonArea3(wall) == Approx(6 * std::sqrt(2.0)));
}

TEST_CASE("triangulate: degenerate polygons fall back to the fan", "[geometry3]") {
    const Tris fan4{{0, 1, 2}, {0, 2, 3}};
    const std::vector<vec3> collinear{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
    CHECK(triangulate(collinear) == fan4);
    CHECK(polygonArea3(collinear) == 0);
    const std::vector<vec3> bowtie{{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK(triangulate(bowtie) == fan4);
    const std::vector<vec3> repeated{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK(triangulate(repeated) == fan4);
}

TEST_CASE("polygon area: sums of triangle areas", "[geometry3]") {
    const std::vector<vec3> square{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    CHECK(polygonArea3(square) == Approx(4));
    std::vector<vec3> hexagon;
    for (int i = 0; i < 6; ++i) hexagon.emplace_back(0, std::cos(i * std::numbers::pi / 3), std::sin(i * std::numbers::pi / 3));
    CHECK(polygonArea3(hexagon) == Approx(3 * std::sqrt(3.0) / 2));
    const std::vector<vec3> tri{{1, 1, 1}, {2, 1, 1}, {1, 1, 3}};
    CHECK(polygonArea3(tri) == Approx(1));
    CHECK(polygonArea3(std::span(tri).first(2)) == 0);
}

TEST_CASE("normals: eq (3.11) and Newell, counter-clockwise in xy is +z", "[geometry3]") {
    CHECK(faceNormal({0, 0, 0}, {1, 0, 0}, {0, 1, 0}) == vec3(0, 0, 1));
    CHECK(faceNormal({0, 1, 0}, {1, 0, 0}, {0, 0, 0}) == vec3(0, 0, -1));
    CHECK(faceNormal({0, 0, 0}, {1, 0, 0}, {2, 0, 0}) == vec3(0));
    const vec3 n = faceNormal({0, 0, 0}, {0, 3, 0}, {0, 3, 4});  // in x = 0: turning left seen from +x
    CHECK(n == vec3(1, 0, 0));
    const std::vector<vec3> ell{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    CHECK(polygonNormal(ell) == vec3(0, 0, 1));
    // At the L's reflex corner eq (3.11) points the other way; Newell's does not.
    CHECK(faceNormal(ell[2], ell[3], ell[4]) == vec3(0, 0, -1));
    const std::vector<vec3> clockwise{{0, 0, 5}, {0, 1, 5}, {1, 1, 5}, {1, 0, 5}};
    CHECK(polygonNormal(clockwise) == vec3(0, 0, -1));
    const std::vector<vec3> tilted{{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 1}};  // in the plane z = y
    const vec3 t = polygonNormal(tilted);
    CHECK(t.x == Approx(0).margin(1e-15));
    CHECK(t.y == Approx(-std::sqrt(0.5)));
    CHECK(t.z == Approx(std::sqrt(0.5)));
    CHECK(polygonNormal(std::vector<vec3>{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}) == vec3(0));
}

TEST_CASE("segment/polygon: over the triangulation, diagonals included", "[geometry3]") {
    const std::vector<vec3> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};  // diagonal (0, 2)
    struct Case {
        vec3 o0, o1;
        bool hit;
    };
    const Case cases[] = {
        {{0.5, 0.5, -1}, {0.5, 0.5, 1}, true},    // through the centre, on the diagonal
        {{0.3, 0.3, 1}, {0.7, 0.7, -1}, true},    // slanted, through the diagonal
        {{0.25, 0.75, -1}, {0.25, 0.75, 1}, true},
        {{0.2, 0.2, 0}, {0.8, 0.8, 0}, true},     // coplanar, along the diagonal
        {{0, 0, 0}, {-1, -1, 0}, false},          // coplanar, from the diagonal's end outwards
        {{2, 2, -1}, {2, 2, 1}, false},
        {{1, 1, -1}, {1, 1, 1}, false},           // through a vertex
        {{0.5, 0, -1}, {0.5, 0, 1}, false},       // through a side
        {{0, 0, 0}, {1, 0, 0}, false},            // along a side
        {{0.5, 0.5, 0.1}, {0.5, 0.5, 1}, false},  // above
    };
    eachFrame([&](const auto& f) {
        std::vector<vec3> poly;
        for (const vec3& p : square) poly.push_back(f(p));
        for (const Case& c : cases) {
            CAPTURE(c.o0.x, c.o0.y, c.o0.z, c.o1.x, c.o1.y, c.o1.z);
            CHECK(segmentPolygon(f(c.o0), f(c.o1), poly) == c.hit);
        }
    });
    // The L: through its notch is outside.
    const std::vector<vec3> ell{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    CHECK_FALSE(segmentPolygon({1.5, 1.5, -1}, {1.5, 1.5, 1}, ell));
    CHECK(segmentPolygon({0.5, 1.5, -1}, {0.5, 1.5, 1}, ell));
}

TEST_CASE("polygon/polygon: crossing, sharing, duplicates", "[geometry3]") {
    const std::vector<vec3> floor{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};  // diagonal (0,0)-(1,1)
    // An upright square in the plane x + y = 1 whose diagonal meets the
    // floor's exactly at (0.5, 0.5, 0): every edge of either triangulation
    // misses the other's open triangles, the diagonals meet.
    const std::vector<vec3> upright{{1, 0, -1}, {0, 1, -1}, {0, 1, 1}, {1, 0, 1}};
    REQUIRE(triangulate(upright) == Tris{{0, 1, 2}, {0, 2, 3}});
    struct Case {
        std::vector<vec3> q;
        bool hit;
    };
    const std::vector<Case> cases{
        {upright, true},
        {{{3, 0, -1}, {0, 3, -1}, {0, 3, 1}, {3, 0, 1}}, false},          // the same, moved off
        {{{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}}, false},            // coplanar, a shared side
        {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, false},            // a wall on a side
        {{{1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}}, false},            // a shared corner
        {{{0.5, 0.5, 0}, {2, 0.5, 0}, {2, 2, 0}, {0.5, 2, 0}}, true},     // coplanar, overlapping
        {floor, true},                                                    // the same face
        {{floor[3], floor[2], floor[1], floor[0]}, true},                 // the same, reversed
        {{floor[1], floor[2], floor[3], floor[0]}, true},                 // the same, other diagonal
        {{{0.5, -1, -1}, {0.5, 2, -1}, {0.5, 2, 1}, {0.5, -1, 1}}, true}, // cutting through
    };
    eachFrame([&](const auto& f) {
        std::vector<vec3> p;
        for (const vec3& v : floor) p.push_back(f(v));
        for (std::size_t i = 0; i < cases.size(); ++i) {
            std::vector<vec3> q;
            for (const vec3& v : cases[i].q) q.push_back(f(v));
            CAPTURE(i);
            CHECK(polygonsIntersect(p, q) == cases[i].hit);
            CHECK(polygonsIntersect(q, p) == cases[i].hit);
        }
    });
}
