#include "sema/element_facts.hpp"

namespace g2d::sema {

const std::vector<ElementFact>& elementFacts() {
    using F = ir::ElemFact;
    using T = ir::TypeKind;
    static const std::vector<ElementFact> facts = {
        {"pos", F::Pos, T::Vec2, false, "vec2: the node's position"},
        {"age", F::Age, T::Int, true, "int: the step that created the element (0: the axiom)"},
        {"id", F::Id, T::Int, true, "int: the element's id (never reused)"},
        {"degree", F::Degree, T::Int, false, "int: the node's edges, both directions"},
        {"in_degree", F::InDegree, T::Int, false, "int: the node's incoming edges"},
        {"out_degree", F::OutDegree, T::Int, false, "int: the node's outgoing edges"},
    };
    return facts;
}

const ElementFact* findElementFact(const std::string& name, bool isNode) {
    for (const auto& f : elementFacts())
        if (name == f.name && (isNode || f.onEdges)) return &f;
    return nullptr;
}

}  // namespace g2d::sema
