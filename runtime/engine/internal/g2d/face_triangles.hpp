#pragma once
// The triangles that draw a face, found once in its own plane and shared by
// every consumer that needs triangles: the --view page, OBJ's triangle mode
// and glTF. A face (2D or 3D, planar or nearly so, with holes and bent sides)
// is projected along its Newell normal and ear-clipped (polygon_triangles).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "g2d/edge_paths.hpp"
#include "g2d/graph.hpp"

namespace g2d::rt {

enum class FaceShapeProblem : std::uint8_t {
    None,
    Collinear,      // every corner on one line (or one point): no area to cover
    SelfCrossing,   // the outline crosses itself: no triangles cover it exactly
};

struct FaceTriangles {
    std::vector<PathPoint> points;   // the outer ring's points, then each hole's (bends included)
    std::vector<vec3> positions;     // by point
    // Indices into `points`, each running the face's way round: counter-
    // clockwise seen from the tip of `normal`.
    std::vector<std::array<std::uint32_t, 3>> triangles;
    vec3 normal{0.0};                // unit; zero when the face has no area
    FaceShapeProblem problem = FaceShapeProblem::None;   // when set, `triangles` is not to be used
};

FaceTriangles triangulateFace(const Graph& g, FaceId f);

// What is wrong with a face that cannot be triangulated, for an error
// message: "face 12 (Wall, corners 3 4 9 10) cannot be drawn as triangles: ...".
std::string faceShapeMessage(const Graph& g, FaceId f, const std::string& kindName, FaceShapeProblem problem);

}  // namespace g2d::rt
