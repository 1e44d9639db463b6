#pragma once
// 3D geometry for G^3's intersection tests and face conditions (Laganeckiene
// 2012 §3.2, §3.4; docs/research/g3-thesis-digest.md §7, OC-42..OC-46). Pure
// functions, no state.
//
// Tolerance (OC-45): each call takes eps = 1e-9 x the size of its
// configuration (the largest coordinate difference from its first point), so
// answers do not change when a model is scaled or moved. Where the thesis
// tests `= 0` we test `<= eps` (a length), or a sine <= 1e-9 for parallel.
//
// Touching (OC-45, OC-42):
//  - segment/segment is closed: distance <= h intersects (the thesis: "if
//    this distance is bigger than h, then edges do not intersect"; with h = 0,
//    coinciding vertices count, §3.2). Edges that share a node need
//    segmentsIntersectSharing, which ignores the contact at that node.
//  - segment/triangle, triangle/triangle and the polygon tests are open: they
//    intersect only where the open segment meets the open triangle (the
//    thesis's strict u, v > 0, u + v < 1, 0 < t < l, by eps). Touching a side
//    or a vertex is not an intersection, so primitives that share a node or a
//    side need no exclusion: they do not intersect unless they overlap beyond
//    the shared part (e.g. a coplanar fold-over, or an edge lying inside the
//    face).
#include <array>
#include <span>
#include <vector>

#include "g2d/vec_math.hpp"

namespace g2d::rt {

// --- Segment / segment (§3.2.1) ---

// Distance between segments a0a1 and b0b1, by the thesis's cases: parallel
// (‖da × db‖ <= eps): the corrected line distance ‖w − (w·d̂)d̂‖ (OC-5) with
// the gap between the projected intervals; otherwise the lines' closest
// points, eqs (3.3)/(3.4). Where those fall outside a segment we clamp (the
// minimum is then at an endpoint) instead of checking s, t against −h and
// l + h: that gives the true distance between the cylinders' axes, so nearly
// parallel edges side by side are caught even though their lines meet far
// away (the thesis's test misses them). Zero-length segments are points.
double segmentDistance(vec3 a0, vec3 a1, vec3 b0, vec3 b1);

// Edges as cylinders of thickness h (§3.2.1): intersect when their axes come
// within h (closed, see above).
bool segmentsIntersect(vec3 a0, vec3 a1, vec3 b0, vec3 b1, double h);

// Two edges that share the node `shared` (shared–a and shared–b): near the
// node their cylinders always overlap, so that contact is ignored. They
// intersect only when one lies wholly within h of the other, e.g. an edge
// folded back onto its neighbour; with h = 0, when they are collinear and
// overlap. Tested at the far ends: the distance to the other segment only
// grows going away from the shared node.
bool segmentsIntersectSharing(vec3 shared, vec3 a, vec3 b, double h);

// h for two edges (OC-43): an edge is a cylinder of its end nodes' mean
// radius (the cone's radius at its middle; one h per pair, as the thesis
// has), and two cylinders touch when their axes are the sum of their radii
// apart; the max would let a thin edge sink half into a thick one. The
// thesis gives thickness only to edges without faces: pass 0 radii for an
// edge that has faces.
double edgeThickness(double a0Radius, double a1Radius, double b0Radius, double b1Radius);

// --- Segment / triangle (§3.2.2), triangle / triangle (§3.2.3) ---

// Open segment o0o1 against the open triangle p0p1p2: eqs (3.8)–(3.10) with
// strict inequalities; when parallel and coplanar, the thesis's 2D case (all
// triangle vertices on one side of the segment's line, or both segment ends
// beyond one triangle side: apart; on a line counts as beyond). The cases are
// told apart by the ends' distances from the plane (both within eps:
// coplanar), one tolerance for "parallel" and for "t = 0". No thickness (the
// thesis has none here). A degenerate triangle or segment has no interior
// and never intersects.
bool segmentTriangle(vec3 o0, vec3 o1, vec3 p0, vec3 p1, vec3 p2);

// The six edge/triangle tests of §3.2.3, plus, for coplanar triangles, one
// centroid-inside test: that is the one overlap the edges miss (two equal
// triangles, every edge on the other's boundary).
bool trianglesIntersect(vec3 p0, vec3 p1, vec3 p2, vec3 q0, vec3 q1, vec3 q2);

// --- Polygons (§3.2.4, §3.4) ---

// The triangles of `polygon` (indices into it; each triangle in the polygon's
// cyclic order, so with its orientation; the list sorted). Follows §3.2.4: a
// diagonal is kept if it crosses no polygon side and no kept diagonal and its
// midpoint is inside (crossing test), until the polygon is all triangles.
// Choices:
//  - order (OC-46): shortest diagonal first (the thesis's suggested
//    improvement), ties to the lower index pair; fuller triangles, and a
//    non-planar quad splits along its shorter diagonal whichever node the
//    face lists first.
//  - 2D view: drop the axis of the largest Newell-normal component, not the
//    AABB's smallest extent: a wall in the plane x = y that is lower than it
//    is wide projects to a line on dropping the smallest extent (z).
//  - fallback: when no such triangulation exists (collinear points, a
//    self-crossing outline, repeated vertices), the fan from vertex 0.
// O(n^3) for n vertices: faces have few.
std::vector<std::array<int, 3>> triangulate(std::span<const vec3> polygon);

// Sum of the areas of triangulate()'s triangles (§3.4: "firstly
// triangulating the face and then adding together areas of triangles").
// For a non-planar face this depends on the diagonals, hence their fixed
// order above (OC-27).
double polygonArea3(std::span<const vec3> polygon);

// Eq (3.11): the unit normal at p between its neighbours in the face,
// (next − p) × (prev − p): counter-clockwise seen from +z gives +z. Zero when
// the three are collinear.
vec3 faceNormal(vec3 prev, vec3 p, vec3 next);

// Newell's normal of the whole polygon, unit (zero if degenerate): the same
// orientation as eq (3.11) at a convex corner, and defined for non-planar
// faces and at reflex corners.
vec3 polygonNormal(std::span<const vec3> polygon);

// Open segment against a polygon's triangulation. A diagonal is inside the
// face, so meeting a diagonal's open interior also counts: a segment
// through a square's centre would otherwise slip between its two triangles.
bool segmentPolygon(vec3 o0, vec3 o1, std::span<const vec3> polygon);

// Polygon against polygon over their triangulations, likewise (a triangle is
// a polygon of three).
bool polygonsIntersect(std::span<const vec3> p, std::span<const vec3> q);

// --- Thick edges against faces, and the plane's tests (geometry3_more.cpp) ---

// The distance between the closed segment o0o1 and the closed triangle
// p0p1p2 (0 when they meet): the segment's ends against the triangle, and
// the segment against its three sides, unless the segment crosses it.
double segmentTriangleDistance(vec3 o0, vec3 o1, vec3 p0, vec3 p1, vec3 p2);

// A thick edge (a cylinder of `radius` about o0o1, §16.8) against a face:
// the open test of segmentPolygon, or, for radius > 0, the axis within
// radius of the face's triangulation (closed, as edge against edge). An
// edge with one end on a corner of the face (`shared`: 0 or 1, -1 for
// none) touches it there, so only its far end is measured: the distance to
// a convex piece grows along the edge from a point on it.
bool thickSegmentPolygon(vec3 o0, vec3 o1, double radius, int shared, std::span<const vec3> polygon);

// In the plane (a 2D grammar, §16.8), a face is an area and an element
// intersects it by crossing its outline: the open segment has points both
// strictly inside and strictly outside the polygon (z is ignored). Lying
// inside it, along its sides or outside is not intersecting.
bool segmentCrossesOutline(vec3 o0, vec3 o1, std::span<const vec3> polygon);
// Some side of either crosses the other's outline (containment is nesting, not intersecting).
bool outlinesCross(std::span<const vec3> p, std::span<const vec3> q);

}  // namespace g2d::rt
