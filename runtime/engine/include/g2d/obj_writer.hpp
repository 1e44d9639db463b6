#pragma once
// The graph as a Wavefront OBJ: a vertex per live node (z = 0 in 2D), then
// the faces, grouped by kind (`g Kind`, the kinds in declaration order, each
// kind's faces by id), corners in order (counter-clockwise is the front).
// A face with holes is written as the triangles that cover it (OBJ faces
// have none: polygon_triangles.hpp), counter-clockwise too.
// Edges are written as line elements (`l`) in a group `edges`, so that an
// edge-only model still shows its skeleton.
#include <string>

#include "g2d/graph.hpp"
#include "g2d/json_writer.hpp"

namespace g2d::rt {

std::string writeObj(const Graph& g, const JsonSchema& schema);
// The same text, streamed into `out`.
void writeObj(const Graph& g, const JsonSchema& schema, TextOut& out);

}  // namespace g2d::rt
