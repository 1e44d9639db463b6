#pragma once
// Bent edges (Merrell 2023, Appendix B): "we traverse each edge in the
// graph, divide it into small segments and bend each segment by a random
// angle"; "the final positions are found using linear least squares …
// while preserving all cycles".
//
// After the derivation, each edge of a kind with `bend = A` is cut into
// n = max(1, round(length / segment)) segments (at most kMaxBendSegments).
// Each segment gets a heading offset: uniform noise in [-A, A] per segment,
// averaged over a window of `smooth` segments (a low-pass filter) and summed
// along the edge (so the edge wanders instead of zigzagging). Segment k's
// wanted vector is the edge's vector / n turned by its offset.
//
// One sparse least-squares solve (Eigen's SimplicialLDLT on the normal
// equations) then places every bend point and every node whose edges are all
// bent: each segment's end minus its start should be its wanted vector
// (weight 1), and each such node should stay where the drawing put it
// (weight 1 / (4 n̄), n̄ the mean segments per bent edge), so the wander
// adds up along paths and the error of each cycle is shared by its
// segments. Nodes with an edge that does not bend stay where they are, so
// straight edges keep their angles. Cycles stay closed: every edge still
// runs from its source node to its target node.
//
// A bent drawing that is not planar (two polylines cross or overlap, or come
// within the layout's clearance of each other away from a shared node) is
// drawn again with the offending edges' offsets halved, up to
// kBendRounds times; what still conflicts then is drawn straight, as the
// derivation left it (Merrell's "Careful Bending" refuses such a result).
// `reduced` counts the edges whose bend was cut; --stats reports it.
#include "g2d/angle_step.hpp"
#include "g2d/graph.hpp"
#include "g2d/rng.hpp"

namespace g2d::rt {

inline constexpr int kMaxBendSegments = 1000;
inline constexpr int kBendRounds = 6;

struct BendResult {
    long long bent = 0;      // edges drawn bent (or straight within their one segment)
    long long reduced = 0;   // edges whose bend was cut (halved, or undone) to keep the drawing planar
};

// Draws from `rng` (per bent edge in id order: its n + smooth - 1 offsets),
// moves nodes (Graph::setPos) and sets the edges' bends (Graph::setEdgeBend).
// Does nothing, and draws nothing, when no edge kind bends.
BendResult bendEdges(Graph& g, const AngleLayoutSpec& spec, Rng& rng);

}  // namespace g2d::rt
