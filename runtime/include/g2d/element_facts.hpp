#pragma once
// The facts every element has besides its declared attributes (`n.pos`,
// `e.length`, `f.area`, ...): one list, from which the fact enum, the
// interpreter's reader (elementFact) and the functions generated code calls
// (fact::NAME) are all made, and which the checker and the editor read.
#include <cstdint>

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

// X(Id, name, C++ type, type name, classes, meaning)
#define G2D_ELEMENT_FACTS(X)                                                                                          \
    X(Pos, pos, vec2, "vec2", kOnNodes, "the node's position")                                                       \
    X(Age, age, long long, "int", kOnNodes | kOnEdges | kOnFaces, "the step that created the element (0: the axiom)") \
    X(Id, id, long long, "int", kOnNodes | kOnEdges | kOnFaces, "the element's id (never reused)")                   \
    X(Degree, degree, long long, "int", kOnNodes, "the node's edges, both directions")                               \
    X(InDegree, in_degree, long long, "int", kOnNodes, "the node's incoming edges")                                   \
    X(OutDegree, out_degree, long long, "int", kOnNodes, "the node's outgoing edges")                                \
    X(Faces, faces, long long, "int", kOnNodes | kOnEdges,                                                           \
      "the faces the node is a corner of; for an edge, the faces with a side between its ends")                      \
    X(Length, length, double, "float", kOnEdges, "the distance between the edge's ends")                             \
    X(Direction, direction, vec2, "vec2", kOnEdges, "the unit vector from the edge's source to its target")          \
    X(Corners, corners, long long, "int", kOnFaces, "the face's corner count")                                       \
    X(Area, area, double, "float", kOnFaces, "the face's area (by its corners' positions)")                          \
    X(SignedArea, signed_area, double, "float", kOnFaces,                                                            \
      "the face's area, positive when its corners run counter-clockwise (y up)")                                     \
    X(Perimeter, perimeter, double, "float", kOnFaces, "the face's perimeter")                                       \
    X(Centroid, centroid, vec2, "vec2", kOnFaces, "the mean of the face's corners (as G^3 defines it)")              \
    X(Neighbours, neighbours, long long, "int", kOnFaces, "the faces sharing a side with the face")

enum class ElemFact : std::uint8_t {
#define G2D_FACT_ID(id, name, type, typeName, classes, meaning) id,
    G2D_ELEMENT_FACTS(G2D_FACT_ID)
#undef G2D_FACT_ID
};

struct ElementFactEntry {
    ElemFact id;
    const char* name;
    const char* typeName;   // "int", "float", "vec2"
    std::uint8_t classes;
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
inline long long age(const Graph& g, ElemClass c, std::uint32_t id) {
    return c == ElemClass::Edge ? g.edgeAge(id) : c == ElemClass::Face ? g.faceAge(id) : g.nodeAge(id);
}
inline long long id(const Graph&, ElemClass, std::uint32_t id) { return static_cast<long long>(id); }
inline long long degree(const Graph& g, ElemClass, std::uint32_t id) { return g.degree(id); }
inline long long in_degree(const Graph& g, ElemClass, std::uint32_t id) { return g.inDegree(id); }
inline long long out_degree(const Graph& g, ElemClass, std::uint32_t id) { return g.outDegree(id); }
inline long long faces(const Graph& g, ElemClass c, std::uint32_t id) {
    return c == ElemClass::Edge ? g.sideFaceCount(g.source(id), g.target(id)) : g.faceCountAt(id);
}
inline double length(const Graph& g, ElemClass, std::uint32_t id) { return finite(rt::length(g.pos(g.target(id)) - g.pos(g.source(id)))); }
inline vec2 direction(const Graph& g, ElemClass, std::uint32_t id) { return rt::normalize(g.pos(g.target(id)) - g.pos(g.source(id))); }
inline long long corners(const Graph& g, ElemClass, std::uint32_t id) { return g.cornerCount(id); }
inline double area(const Graph& g, ElemClass, std::uint32_t id) { return finite(g.area(id)); }
inline double signed_area(const Graph& g, ElemClass, std::uint32_t id) { return finite(g.signedArea(id)); }
inline double perimeter(const Graph& g, ElemClass, std::uint32_t id) { return finite(g.perimeter(id)); }
inline vec2 centroid(const Graph& g, ElemClass, std::uint32_t id) { return finite(g.centroid(id)); }
inline long long neighbours(const Graph& g, ElemClass, std::uint32_t id) { return g.neighbourCount(id); }

}  // namespace fact

}  // namespace g2d::rt
