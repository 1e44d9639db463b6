#pragma once
// The classes of graph element. Kinds, attributes, drawing and the writers
// address an element by (class, id), so that faces can join nodes and edges
// without a second flag beside every `isEdge`.
#include <cstdint>

namespace g2d::rt {

enum class ElemClass : std::uint8_t { Node, Edge, Face };

// "node", "edge", "face": as the language writes it.
constexpr const char* elemClassName(ElemClass c) {
    return c == ElemClass::Edge ? "edge" : c == ElemClass::Face ? "face" : "node";
}

}  // namespace g2d::rt
