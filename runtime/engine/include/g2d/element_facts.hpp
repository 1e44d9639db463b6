#pragma once
// The facts every element has besides its declared attributes (`n.pos`,
// `e.length`, `f.area`, ...): one list, from which the fact enum, the
// interpreter's reader (elementFact) and the functions generated code calls
// (fact::NAME) are all made, and which the checker and the editor read.
#include <cstdint>

#include "g2d/element_scope.hpp"
#include "g2d/graph.hpp"
#include "g2d/ops.hpp"
#include "g2d/value.hpp"
#include "g2d/vec_math.hpp"

namespace g2d::rt {

// Which classes of element have a fact (a bit per ElemClass).
inline constexpr std::uint8_t kOnNodes = 1, kOnEdges = 2, kOnFaces = 4;
constexpr std::uint8_t classBit(ElemClass c) {
    return c == ElemClass::Edge ? kOnEdges : c == ElemClass::Face ? kOnFaces : kOnNodes;
}

// In which space a fact exists: both, or only 2D or 3D grammars (`space 3d;`).
// A 2D and a 3D fact may share a name (`pos` is a vec2 or a vec3).
inline constexpr std::uint8_t kIn2d = 1, kIn3d = 2, kInBoth = 3;

// What can change a fact besides a write to the element itself (its
// position, radius or kind): a bit each. The lowering reads these to know
// which changes a rule that reads the fact must see (lower/fact_reads.hpp);
// a new fact declares them here and nowhere else.
inline constexpr std::uint8_t kReadsOwn = 0;           // only the element's own record
inline constexpr std::uint8_t kReadsEnds = 1;          // the positions of an edge's ends or a face's corners (any kind)
inline constexpr std::uint8_t kReadsEdgesAt = 2;       // the edges at a node (an edge: at its ends), of any kind
inline constexpr std::uint8_t kReadsFacesAt = 4;       // the faces at a node or along an edge, of any kind
inline constexpr std::uint8_t kReadsFaceSides = 8;     // the faces sharing a side or corner with a face
inline constexpr std::uint8_t kReadsCorners = 16;      // a face's corner list
inline constexpr std::uint8_t kReadsGenerations = 32;  // generation stamps, which a run keeps only when read

// X(Id, function, name, C++ type, type name, classes, spaces, reads, meaning)
#define G2D_ELEMENT_FACTS(X)                                                                                                                \
    X(Pos, pos, pos, vec2, "vec2", kOnNodes, kIn2d, kReadsOwn, "the node's position")                                                       \
    X(Pos3, pos3, pos, vec3, "vec3", kOnNodes, kIn3d, kReadsOwn, "the node's position")                                                     \
    X(Radius, radius, radius, double, "float", kOnNodes, kIn3d, kReadsOwn,                                                                  \
      "the node's radius (G^3: the thickness of its edges; 0 unless set)")                                                                  \
    X(Age, age, age, long long, "int", kOnNodes | kOnEdges | kOnFaces, kInBoth, kReadsOwn,                                                  \
      "the step that created the element (0: the axiom)")                                                                                   \
    X(Generation, generation, generation, long long, "int", kOnNodes | kOnEdges | kOnFaces, kInBoth, kReadsGenerations,                     \
      "one more than the highest generation among the elements matched by the application that created it (0: the axiom; the thesis tool's .generation)") \
    X(Id, id, id, long long, "int", kOnNodes | kOnEdges | kOnFaces, kInBoth, kReadsOwn, "the element's id (never reused)")                  \
    X(Degree, degree, degree, long long, "int", kOnNodes | kOnEdges, kInBoth, kReadsEdgesAt,                                                \
      "the node's edges, both directions; for an edge, the other edges at its ends (G^3's neighbouring edges)")                             \
    X(InDegree, in_degree, in_degree, long long, "int", kOnNodes, kInBoth, kReadsEdgesAt, "the node's incoming edges")                      \
    X(OutDegree, out_degree, out_degree, long long, "int", kOnNodes, kInBoth, kReadsEdgesAt, "the node's outgoing edges")                   \
    X(Faces, faces, faces, long long, "int", kOnNodes | kOnEdges, kInBoth, kReadsFacesAt,                                                   \
      "the faces the node is a corner of; for an edge, the faces with a side between its ends")                                             \
    X(Length, length, length, double, "float", kOnEdges, kIn2d, kReadsEnds, "the distance between the edge's ends")                         \
    X(Length3, length3, length, double, "float", kOnEdges, kIn3d, kReadsEnds, "the distance between the edge's ends")                       \
    X(Direction, direction, direction, vec2, "vec2", kOnEdges, kIn2d, kReadsEnds,                                                           \
      "the unit vector from the edge's source to its target")                                                                               \
    X(Direction3, direction3, direction, vec3, "vec3", kOnEdges, kIn3d, kReadsEnds,                                                         \
      "the unit vector from the edge's source to its target")                                                                               \
    X(Midpoint, midpoint, midpoint, vec2, "vec2", kOnEdges, kIn2d, kReadsEnds, "the point halfway between the edge's ends")                 \
    X(Midpoint3, midpoint3, midpoint, vec3, "vec3", kOnEdges, kIn3d, kReadsEnds, "the point halfway between the edge's ends")               \
    X(Corners, corners, corners, long long, "int", kOnFaces, kInBoth, kReadsCorners, "the face's corner count")                             \
    X(Area, area, area, double, "float", kOnFaces, kIn2d, kReadsEnds | kReadsCorners, "the face's area (by its corners' positions)")        \
    X(Area3, area3, area, double, "float", kOnFaces, kIn3d, kReadsEnds | kReadsCorners,                                                     \
      "the face's area: the sum of its triangles (G^3: shortest diagonals first)")                                                          \
    X(SignedArea, signed_area, signed_area, double, "float", kOnFaces, kIn2d, kReadsEnds | kReadsCorners,                                   \
      "the face's area, positive when its corners run counter-clockwise (y up)")                                                            \
    X(Perimeter, perimeter, perimeter, double, "float", kOnFaces, kIn2d, kReadsEnds | kReadsCorners, "the face's perimeter")                \
    X(Perimeter3, perimeter3, perimeter, double, "float", kOnFaces, kIn3d, kReadsEnds | kReadsCorners, "the face's perimeter")              \
    X(Centroid, centroid, centroid, vec2, "vec2", kOnFaces, kIn2d, kReadsEnds | kReadsCorners, "the mean of the face's corners (as G^3 defines it)") \
    X(Centroid3, centroid3, centroid, vec3, "vec3", kOnFaces, kIn3d, kReadsEnds | kReadsCorners,                                            \
      "the mean of the face's corners (as G^3 defines it)")                                                                                 \
    X(Normal, normal, normal, vec3, "vec3", kOnFaces, kIn3d, kReadsEnds | kReadsCorners,                                                    \
      "the face's unit normal (Newell's; counter-clockwise corners seen from its tip)")                                                     \
    X(Neighbours, neighbours, neighbours, long long, "int", kOnFaces, kInBoth, kReadsFaceSides, "the faces sharing a side with the face")   \
    X(Touching, touching, touching, long long, "int", kOnFaces, kInBoth, kReadsFaceSides,                                                   \
      "the faces sharing at least a corner with the face (G^3's neighbouring faces)")                                                       \
    X(Lo, lo, lo, vec2, "vec2", kOnEdges | kOnFaces, kIn2d, kReadsEnds | kReadsCorners,                                                     \
      "the least x and y of its nodes (an edge's ends, a face's corners): `f.lo.x > 1` holds when every corner has x > 1")                  \
    X(Hi, hi, hi, vec2, "vec2", kOnEdges | kOnFaces, kIn2d, kReadsEnds | kReadsCorners,                                                     \
      "the greatest x and y of its nodes: `f.hi.x < 1` holds when every corner has x < 1")                                                  \
    X(Lo3, lo3, lo, vec3, "vec3", kOnEdges | kOnFaces, kIn3d, kReadsEnds | kReadsCorners,                                                   \
      "the least x, y and z of its nodes (an edge's ends, a face's corners): `f.lo.z > 1` holds when every corner has z > 1")               \
    X(Hi3, hi3, hi, vec3, "vec3", kOnEdges | kOnFaces, kIn3d, kReadsEnds | kReadsCorners,                                                   \
      "the greatest x, y and z of its nodes: `f.hi.z < 1` holds when every corner has z < 1")

enum class ElemFact : std::uint8_t {
#define G2D_FACT_ID(id, fn, name, type, typeName, classes, spaces, reads, meaning) id,
    G2D_ELEMENT_FACTS(G2D_FACT_ID)
#undef G2D_FACT_ID
};

struct ElementFactEntry {
    ElemFact id;
    const char* function;   // in namespace fact (below)
    const char* name;       // as grammars write it
    const char* typeName;   // "int", "float", "vec2", "vec3"
    std::uint8_t classes;
    std::uint8_t spaces;
    std::uint8_t reads;     // kReads* bits
    const char* meaning;
};
// Every fact, in the list's order.
const ElementFactEntry* elementFactEntries(std::size_t& count);
const ElementFactEntry& elementFactEntry(ElemFact id);

// Fact `fact` of element `id` of class `cls` (which has it), as a Value.
Value elementFact(const Graph& g, ElemClass cls, std::uint32_t id, ElemFact fact);

// Each fact as a typed function; generated code calls these with a constant class.
namespace fact {

inline vec2 pos(const Graph& g, ElemClass, std::uint32_t id) { return g.pos(id); }
inline vec3 pos3(const Graph& g, ElemClass, std::uint32_t id) { return g.pos3(id); }
inline double radius(const Graph& g, ElemClass, std::uint32_t id) { return g.radius(id); }
inline long long age(const Graph& g, ElemClass c, std::uint32_t id) {
    return c == ElemClass::Edge ? g.edgeAge(id) : c == ElemClass::Face ? g.faceAge(id) : g.nodeAge(id);
}
inline long long generation(const Graph& g, ElemClass c, std::uint32_t id) {
    return c == ElemClass::Edge ? g.edgeGeneration(id) : c == ElemClass::Face ? g.faceGeneration(id) : g.nodeGeneration(id);
}
inline long long id(const Graph&, ElemClass, std::uint32_t id) { return static_cast<long long>(id); }
// The topological facts count within a compound's scope while one is set (element_scope.hpp).
inline long long nodeDegree(const Graph& g, NodeId n) { return g.scope() ? scoped::degree(g, *g.scope(), n) : g.degree(n); }
// An edge's: the other edges at its ends (each once; a self-loop has one end).
inline long long degree(const Graph& g, ElemClass c, std::uint32_t id) {
    if (c != ElemClass::Edge) return nodeDegree(g, id);
    const NodeId a = g.source(id), b = g.target(id);
    return a == b ? nodeDegree(g, a) - 1 : nodeDegree(g, a) + nodeDegree(g, b) - 2;
}
inline long long in_degree(const Graph& g, ElemClass, std::uint32_t id) {
    return g.scope() ? scoped::inDegree(g, *g.scope(), id) : g.inDegree(id);
}
inline long long out_degree(const Graph& g, ElemClass, std::uint32_t id) {
    return g.scope() ? scoped::outDegree(g, *g.scope(), id) : g.outDegree(id);
}
inline long long faces(const Graph& g, ElemClass c, std::uint32_t id) {
    if (c == ElemClass::Edge)
        return g.scope() ? scoped::sideFaces(g, *g.scope(), g.source(id), g.target(id)) : g.sideFaceCount(g.source(id), g.target(id));
    return g.scope() ? scoped::facesAt(g, *g.scope(), id) : g.faceCountAt(id);
}
inline double length(const Graph& g, ElemClass, std::uint32_t id) { return finite(rt::length(g.pos(g.target(id)) - g.pos(g.source(id)))); }
inline vec2 direction(const Graph& g, ElemClass, std::uint32_t id) { return rt::normalize(g.pos(g.target(id)) - g.pos(g.source(id))); }
inline double length3(const Graph& g, ElemClass, std::uint32_t id) { return finite(rt::length(g.pos3(g.target(id)) - g.pos3(g.source(id)))); }
inline vec3 direction3(const Graph& g, ElemClass, std::uint32_t id) { return rt::normalize(g.pos3(g.target(id)) - g.pos3(g.source(id))); }
inline vec2 midpoint(const Graph& g, ElemClass, std::uint32_t id) { return (g.pos(g.source(id)) + g.pos(g.target(id))) * 0.5; }
inline vec3 midpoint3(const Graph& g, ElemClass, std::uint32_t id) { return (g.pos3(g.source(id)) + g.pos3(g.target(id))) * 0.5; }
inline long long corners(const Graph& g, ElemClass, std::uint32_t id) { return g.cornerCount(id); }
inline double area(const Graph& g, ElemClass, std::uint32_t id) { return finite(g.area(id)); }
inline double signed_area(const Graph& g, ElemClass, std::uint32_t id) { return finite(g.signedArea(id)); }
inline double perimeter(const Graph& g, ElemClass, std::uint32_t id) { return finite(g.perimeter(id)); }
inline vec2 centroid(const Graph& g, ElemClass, std::uint32_t id) { return finite(g.centroid(id)); }
inline double area3(const Graph& g, ElemClass, std::uint32_t id) { return finite(g.area3(id)); }
inline double perimeter3(const Graph& g, ElemClass, std::uint32_t id) { return finite(g.perimeter3(id)); }
inline vec3 centroid3(const Graph& g, ElemClass, std::uint32_t id) { return finite(g.centroid3(id)); }
inline vec3 normal(const Graph& g, ElemClass, std::uint32_t id) { return rt::normalize(g.vectorArea(id)); }
inline long long neighbours(const Graph& g, ElemClass, std::uint32_t id) {
    return g.scope() ? scoped::neighbours(g, *g.scope(), id) : g.neighbourCount(id);
}
inline long long touching(const Graph& g, ElemClass, std::uint32_t id) {
    return g.scope() ? scoped::touching(g, *g.scope(), id) : g.touchingCount(id);
}
// The bounds of an edge's ends or a face's corners (G^3's position condition on every node).
inline vec3 lo3(const Graph& g, ElemClass c, std::uint32_t id) { return g.bounds3(c == ElemClass::Edge, id).lo; }
inline vec3 hi3(const Graph& g, ElemClass c, std::uint32_t id) { return g.bounds3(c == ElemClass::Edge, id).hi; }
inline vec2 lo(const Graph& g, ElemClass c, std::uint32_t id) { const vec3 v = lo3(g, c, id); return {v.x, v.y}; }
inline vec2 hi(const Graph& g, ElemClass c, std::uint32_t id) { const vec3 v = hi3(g, c, id); return {v.x, v.y}; }

}  // namespace fact

}  // namespace g2d::rt
