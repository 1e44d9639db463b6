#pragma once
// The facts every element has besides its declared attributes (`n.pos`,
// `e.age`, ...): one table that the checker and the editor's completion read.
#include <vector>

#include "ir/ir.hpp"

namespace g2d::sema {

struct ElementFact {
    const char* name;
    ir::ElemFact fact;
    ir::TypeKind type;
    bool onEdges;          // every fact is a node's; these are an edge's too
    const char* meaning;   // for completion and hovers
};

const std::vector<ElementFact>& elementFacts();

// The fact `name` of a node (isNode) or an edge, or null.
const ElementFact* findElementFact(const std::string& name, bool isNode);

}  // namespace g2d::sema
