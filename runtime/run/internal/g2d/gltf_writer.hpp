#pragma once
// The model as binary glTF 2.0 (`--gltf FILE.glb`), made with tinygltf
// (Debian's libtinygltf). glTF is y-up: a point (x, y, z) of the grammar is
// (x, z, -y) in the file, so z stays up in every viewer; a 2D grammar lies
// on the ground (z = 0).
// - one mesh (and node) per face kind, named by it, in declaration order:
//   each face as the triangles of triangulateFace (face_triangles.hpp), flat
//   (its own vertices, its normal), a primitive per material;
// - one mesh per edge kind, named by it: an edge whose ends have a radius
//   (G^3's; §16.8: the mean of the two) as an 8-sided tube, the others as
//   lines;
// - materials from the drawing (export_style.hpp): baseColorFactor (linear),
//   alphaMode BLEND when translucent, double-sided, not metallic.
// Faces and edges the drawing hides (`tag` or `fill`/`stroke` `none`) are
// left out, as the --view page leaves them. A face that has no triangles is
// an ExportError. The same graph and styles give the same bytes.
#include <string>

#include "g2d/graph.hpp"
#include "g2d/json_schema.hpp"
#include "g2d/svg_writer.hpp"

namespace g2d::rt {

// `title` names the scene (the grammar's file name).
std::string writeGltf(const Graph& g, const JsonSchema& schema, const ItemMaker& item, const std::string& title);

}  // namespace g2d::rt
