#pragma once
// Merrell 2023's generation keeps faces implicit: every edge names the face
// kind on its left and on its right, and the faces are whatever the planar
// straight-line drawing encloses. traceFaces recovers them, as plain data, so
// the derivation can match and draw faces without storing them.
//
// The usual half-edge walk: each edge gives two half-edges (from->to and
// to->from), the half-edges leaving a vertex are sorted by angle (atan2),
// and after a half-edge u->v a cycle continues with the half-edge that
// follows v->u clockwise round v. Every half-edge lies on exactly one cycle,
// and that cycle's face lies on its left.
#include <vector>

#include "g2d/vec_math.hpp"

namespace g2d::rt {

struct SidedEdge {
    int from = -1, to = -1;     // vertex indices
    int left = -1, right = -1;  // face kinds on the left / right of from->to (-1: no face)
};

struct TracedFace {
    int kind = -1;
    std::vector<int> corners;   // counter-clockwise (positive signed area), distinct
    std::vector<std::vector<int>> holes;   // clockwise rings inside it (islands), each distinct
};

// The bounded faces of the drawing (`position` per vertex, `edges` planar:
// they meet only at shared ends).
//
// - A half-edge's kind is the kind on its left: the edge's `left` for
//   from->to, its `right` for to->from. A face takes the kind most of its
//   boundary half-edges have (ties: the smallest, -1 included), so a drawing
//   whose sides disagree still gives an answer instead of an error.
// - A closed walk that visits a vertex twice (a dangling edge inside a face,
//   a bridge to a hole) is cut at the repeated vertices into simple cycles;
//   the spikes so cut out have no area and vanish. The kind is voted over
//   the kept cycle's own half-edges.
// - Kept: simple cycles with positive signed area, >= 3 corners and kind
//   >= 0. A component's outer boundary and a hole's boundary run clockwise
//   (negative area), so they are never faces; the hole is its own face.
// - Holes: a clockwise cycle is a hole of the face whose cycle is the
//   innermost counter-clockwise one around it (ring_nesting.hpp): an island
//   in the face, or a part of the face's boundary cut off at a repeated
//   vertex (pinched or joined by a bridge). None when that cycle is no face
//   (kind -1) or there is none (the unbounded face). A hole's corners start
//   at its least half-edge's start vertex; holes in the order of those.
// - Order: by each face's least half-edge (edge index * 2, + 1 for
//   to->from); its corners start at that half-edge's start vertex. So the
//   result depends on the input only, not on the walk.
// - Edges with an end out of range, from == to, or an end at a non-finite
//   position are left out (as if absent); nothing throws.
//
// O(E log E) for E edges (the angular sort), plus the holes' nesting:
// O(H x corners of the faces around them) for H clockwise cycles.
std::vector<TracedFace> traceFaces(const std::vector<vec2>& position, const std::vector<SidedEdge>& edges);

}  // namespace g2d::rt
