#pragma once
// A read-only view of a derived graph for embedding programs (grammar.hpp):
// its elements, their kinds, where the nodes are, what the edges join and
// the faces' corners. It keeps embedding programs off the store's own header
// (graph.hpp) and its tree; Grammar::graph() gives the whole store to a
// program that includes it.
//
// Ids are the store's: an element keeps its id for life and ids are never
// reused, so the ids of live elements have gaps. Visit every live node as
//     for (std::uint32_t n = 0; n < view.capacity(ElemClass::Node); ++n)
//         if (view.alive(ElemClass::Node, n)) …
// Other calls expect a live id. A view reads the graph where it is: it sees
// the next derive()'s graph, and is valid while its Grammar lives.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "g2d/elem_class.hpp"
#include "g2d/vec_math.hpp"

namespace g2d {

namespace rt {
class Graph;
}

class GraphView {
public:
    using Id = std::uint32_t;
    // `kindNames`: the grammar's kinds by index, as the JSON output names them.
    GraphView(const rt::Graph& graph, const std::vector<std::string>& kindNames) : graph_(&graph), kindNames_(&kindNames) {}

    // Live elements of a class, and the bound of their ids.
    std::size_t count(rt::ElemClass cls) const;
    std::size_t capacity(rt::ElemClass cls) const;
    bool alive(rt::ElemClass cls, Id id) const;

    // An element's kind: its index among the grammar's kinds, and its name.
    int kind(rt::ElemClass cls, Id id) const;
    const std::string& kindName(rt::ElemClass cls, Id id) const;

    // A node's position (z is 0 unless the grammar is `space 3d;`).
    rt::vec3 position(Id node) const;
    // An edge's ends (from source to target, for a directed kind).
    Id source(Id edge) const;
    Id target(Id edge) const;
    // A face's corners, in order (counter-clockwise is its front).
    std::vector<Id> corners(Id face) const;

private:
    const rt::Graph* graph_;
    const std::vector<std::string>* kindNames_;
};

}  // namespace g2d
