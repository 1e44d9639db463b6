#pragma once
// The graph as a Wavefront OBJ: a vertex per live node (z = 0 in 2D), then
// the faces, grouped by kind (`g Kind`, the kinds in declaration order, each
// kind's faces by id), corners in order (counter-clockwise is the front).
// A face with holes is written as the triangles that cover it (OBJ faces
// have none: polygon_triangles.hpp), counter-clockwise too.
// Edges are written as line elements (`l`) in a group `edges`, so that an
// edge-only model still shows its skeleton.
// Each face has a normal (`vn`, Newell's: the corners run counter-clockwise
// seen from its tip; none for a face without area) that its corners name
// (`f a//n b//n c//n`). With ObjOptions::mtl, a `mtllib` line names the MTL
// and each face takes the material of its fill (`usemtl`, export_style.hpp);
// with `triangles`, every face is written as the triangles of
// triangulateFace (face_triangles.hpp), and a face that has none (its corners
// collinear, or its outline crossing itself) is an error (ExportError).
#include <string>

#include "g2d/graph.hpp"
#include "g2d/json_writer.hpp"
#include "g2d/svg_writer.hpp"
#include "g2d/text_out.hpp"

namespace g2d::rt {

struct ObjOptions {
    bool triangles = false;     // every face as triangles (--obj-triangles)
    TextOut* mtl = nullptr;     // the MTL's sink; none: no materials
    std::string mtlName;        // the MTL as `mtllib` names it (beside the OBJ)
    ItemMaker faceItem;         // the faces' drawings (their fill), with `mtl`
};

std::string writeObj(const Graph& g, const JsonSchema& schema);
// The same text (with options: normals, materials, triangles), streamed into `out`.
void writeObj(const Graph& g, const JsonSchema& schema, TextOut& out, const ObjOptions& options);

}  // namespace g2d::rt
