#pragma once
// Merrell 2023's drawing step (§6.2–6.3, Algorithm 3 lines 4–9): positions
// for an angle graph whose edges have fixed directions. After a rule changes
// the graph, its new vertices are free; the edge equations v1 = v0 + s·u
// (u the edge's direction, s > 0 its length) form a linear system A x = b
// over the free vertices' coordinates and the lengths of the edges touching
// them. Its solutions are x̂ + K_A Λ (x̂ the least-squares solution, K_A a
// basis of A's nullspace); the step samples Λ and keeps the first sample
// whose lengths are within range and whose drawing is planar. After J
// rejected samples, or when the system has no solution, one fixed vertex
// next to a free one (or at an end of a created edge) is freed and the
// system built again, up to I times.
//
// Plain data in, plain data out: the derivation builds the graph after the
// change, and commits the positions only when a drawing is accepted. Every
// random draw comes from the run's Rng, in a fixed order, so a seed fixes
// the result in the interpreter and in compiled grammars alike (the order is
// listed at the top of angle_drawing.cpp).
#include <vector>

#include "g2d/rng.hpp"
#include "g2d/vec_math.hpp"

namespace g2d::rt {

struct AngleEdge {
    int from = -1, to = -1;     // vertex indices; the edge points from `from` to `to`
    double angle = 0;           // that direction, in radians
    double minLength = 0;       // the allowed lengths: minLength <= s <= maxLength,
    double maxLength = 0;       // and s > 0; minLength == maxLength: a rigid edge
    int left = -1, right = -1;  // the area on either side of from -> to (-1: none), for consistentAreas
    double unit = 0;            // > 0: the length must be a whole multiple of it (tiles, stairs)
};

// What lies around a part of a drawing, fixed: AngleStep draws only the
// part a change can move and asks its spatial index for the rest.
struct FixedSegment {
    vec2 a, b;          // an isolated node: a == b
    int endA = -1;      // the part's vertex at a (a fixed one), or -1: a node outside the part
    int endB = -1;
};
class FixedSurroundings {
public:
    virtual ~FixedSurroundings() = default;
    // Appends every fixed edge and isolated node outside the part whose box meets [lo, hi].
    virtual void near(vec2 lo, vec2 hi, std::vector<FixedSegment>& out) const = 0;
};

// The graph after the proposed change.
struct AngleGraph {
    std::vector<vec2> position;   // per vertex: its position (a free vertex's is only a guess)
    std::vector<char> free;       // per vertex: 1 if it may move (the change's new vertices); missing: 0
    std::vector<AngleEdge> edges; // every edge of the graph
    std::vector<char> created;    // per edge: 1 if the change made it (solved even between fixed vertices); missing: 0
    // Null: the graph is the whole drawing. Otherwise it is a part, which
    // holds every edge at a vertex that may be freed, and the rest is here.
    const FixedSurroundings* surroundings = nullptr;
};

struct DrawingSettings {
    int proposals = 5;            // I: systems built (each frees one more vertex)
    int samples = 10;             // J: samples per system
    vec2 canvasLo{0, 0}, canvasHi{0, 0};   // every moved vertex must lie in this closed box (1e-9 relative slack)
    double separation = 1e-6;     // least distance between a vertex and an edge not incident to it
    // Also reject a drawing that puts a component inside a region of another
    // area than its edges name outside it (a hexagon inside a hexagon's face):
    // areasConsistent.
    bool consistentAreas = false;
};

struct DrawingResult {
    bool accepted = false;
    std::vector<int> moved;        // the vertices given a position (free ones and freed ones), ascending;
                                   // empty when not accepted
    std::vector<vec2> position;    // their positions, parallel to `moved` (always finite)
    int systems = 0, samples = 0;  // how many were tried (for statistics)
};

// A sample is accepted when every edge of the system (those with a free end,
// and the created ones) points along its angle with a length in
// [minLength, maxLength] and > 0, every moved vertex is in the canvas, and
// drawingIsPlanar holds for the system's edges against all edges. A free
// vertex without edges is placed uniformly in the canvas; a component of
// free vertices only is translated to a uniform place in it. Input with an
// edge index out of range, a non-finite angle or length, or a fixed vertex
// at a non-finite position is rejected without a system. Nothing to draw (no
// free vertex, no created edge) is accepted with `moved` empty.
DrawingResult drawAngleGraph(const AngleGraph& graph, const DrawingSettings& settings, Rng& rng);

// The planarity test the acceptance uses: no two edges cross or overlap
// (edges sharing an end may not leave it in the same direction), no vertex
// lies within `separation` of an edge it is not an end of or of another
// vertex, and no edge is `separation` long or shorter. Touching at a shared
// end is fine. A loop, an end out of range or a non-finite position makes
// the drawing non-planar. Only pairs involving a vertex of `moved` (or its
// edges) are tested when `moved` is not empty (all zero: nothing is tested);
// every pair otherwise. A few moved vertices cost one scan of the edges.
// `surroundings`: the edges and nodes around a part, tested against it too.
bool drawingIsPlanar(const std::vector<vec2>& position, const std::vector<AngleEdge>& edges, double separation,
                     const std::vector<char>& moved = {}, const FixedSurroundings* surroundings = nullptr);

// Every pair of items that conflict as drawingIsPlanar says (each pair
// once, (lower, higher), sorted), every item tested. An item is an edge
// (from, to), or a lone vertex (v, v); indices into `position`.
std::vector<std::pair<int, int>> conflictingItems(const std::vector<vec2>& position, const std::vector<std::pair<int, int>>& items,
                                                  double separation);

// Whether every connected component that contains a `moved` vertex, or whose
// bounding box meets one that does, lies in a region of the area its edges
// name on their outside: seen from its lowest vertex (then leftmost), the
// area of the wedge below it must be the area of the side facing up of the
// first edge of another component straight below (none: outside everything).
// Assumes a planar drawing. O(components tested × edges).
bool areasConsistent(const std::vector<vec2>& position, const std::vector<AngleEdge>& edges, const std::vector<char>& moved);

}  // namespace g2d::rt
