#pragma once
// Which ring of a plane drawing's face walks a clockwise ring lies in: the
// outer boundary of an island (a separate component) lies in the face
// around it, whose outer ring is the innermost counter-clockwise ring that
// encloses it. That face is the one the island makes a hole in.
#include <vector>

#include "g2d/vec_math.hpp"

namespace g2d::rt {

struct Ring {
    std::vector<int> corners;   // vertex indices, distinct
    double area = 0;            // signed: > 0 counter-clockwise
};

// Per ring: for a clockwise ring (area < 0), the index of the innermost
// counter-clockwise ring strictly around it; otherwise, or when none is, -1.
// The rings are the simple cycles of one planar drawing, so two never cross
// and "around" is decided by one corner of the inner ring that the outer one
// does not share. O(holes x corners of the rings around them).
std::vector<int> enclosingRings(const std::vector<vec2>& position, const std::vector<Ring>& rings);

}  // namespace g2d::rt
