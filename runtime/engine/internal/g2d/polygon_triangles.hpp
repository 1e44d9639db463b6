#pragma once
// Triangles that cover a plane polygon with holes exactly, for formats that
// take no holes (OBJ): ear clipping, each hole first joined to the outer
// ring by a bridge (D. Eberly, "Triangulation by Ear Clipping", 2002).
// Written here rather than taken from a Debian package: the runtime is
// linked into every compiled grammar, so a dependency would be every user's.
// CGAL (libcgal-dev) brings Boost, GMP and minutes of compile time; GLU's
// tessellator (libglu1-mesa-dev) OpenGL libraries and callbacks that may
// make new vertices; Clipper (libpolyclipping-dev) clips but does not
// triangulate; earcut is packaged for Python only.
#include <array>
#include <vector>

#include "g2d/vec_math.hpp"

namespace g2d::rt {

// `outer`: counter-clockwise ring of indices into `points`; `holes`:
// clockwise rings inside it, disjoint (they may touch the outer ring or each
// other at a corner). Returns counter-clockwise triangles of those indices,
// whose areas add up to the outer ring's less the holes'. Collinear corners
// may be left out of every triangle (they add no area). O(n^2) for n corners.
std::vector<std::array<int, 3>> triangulate(const std::vector<vec2>& points, const std::vector<int>& outer,
                                            const std::vector<std::vector<int>>& holes);

}  // namespace g2d::rt
