#pragma once
// The scope of a compound command (G^3, Laganeckiene 2012, §3.3.2): its
// initial primitive with the primitives under it, and every primitive the
// compound has created so far. While a graph has a scope set
// (Graph::setScope), the topological facts — degrees, face counts,
// `neighbours`, `touching` — count only the scope's elements
// (element_facts.hpp), so a compound's conditions read the same on an
// isolated face as on one among others.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/value.hpp"

namespace g2d::rt {

class ElementScope {
public:
    void add(ElemClass c, std::uint32_t id) {
        auto& v = ids(c);
        auto at = std::lower_bound(v.begin(), v.end(), id);
        if (at == v.end() || *at != id) v.insert(at, id);
    }
    bool has(ElemClass c, std::uint32_t id) const {
        const auto& v = ids(c);
        return std::binary_search(v.begin(), v.end(), id);
    }
    // A primitive and those under it: an edge's ends; a face's corners and
    // the edges along its sides.
    void addWithParts(const Graph& g, ElemClass c, std::uint32_t id);
    std::size_t size(ElemClass c) const { return ids(c).size(); }
    const std::vector<std::uint32_t>& nodes() const { return nodes_; }   // sorted

    // The compound instance the scope is of: the compound, its lets' values,
    // and the scope of the instance it runs within (none at the top).
    int compound = -1;
    std::vector<Value> values;
    const ElementScope* parent = nullptr;

private:
    std::vector<std::uint32_t>& ids(ElemClass c) { return c == ElemClass::Edge ? edges_ : c == ElemClass::Face ? faces_ : nodes_; }
    const std::vector<std::uint32_t>& ids(ElemClass c) const {
        return c == ElemClass::Edge ? edges_ : c == ElemClass::Face ? faces_ : nodes_;
    }
    std::vector<std::uint32_t> nodes_, edges_, faces_;   // sorted
};

// `C.name` (compound C's let `slot`) as the instance of C that the graph's
// scope lies within has it (std::logic_error outside one: the checker
// lets only rules that run within C read it).
const Value& compoundValue(const Graph& g, int compound, int slot);

// The topological facts counted within a scope.
namespace scoped {
long long degree(const Graph& g, const ElementScope& s, NodeId n);
long long inDegree(const Graph& g, const ElementScope& s, NodeId n);
long long outDegree(const Graph& g, const ElementScope& s, NodeId n);
long long facesAt(const Graph& g, const ElementScope& s, NodeId n);
long long sideFaces(const Graph& g, const ElementScope& s, NodeId u, NodeId v);
long long neighbours(const Graph& g, const ElementScope& s, FaceId f);
long long touching(const Graph& g, const ElementScope& s, FaceId f);
}  // namespace scoped

}  // namespace g2d::rt
