#pragma once
// The facts every element has besides its declared attributes (`n.pos`,
// `e.length`, `f.area`, ...), as the checker and the editor's completion
// see them: the runtime's list (g2d/element_facts.hpp), typed.
#include <vector>

#include "ir/ir.hpp"

namespace g2d::sema {

struct ElementFact {
    const char* name;
    ir::ElemFact fact;
    ir::TypeKind type;
    std::uint8_t classes;  // rt::kOnNodes | kOnEdges | kOnFaces
    std::uint8_t spaces;   // rt::kIn2d | kIn3d
    std::string meaning;   // for completion and hovers: "type: what it is"
};

const std::vector<ElementFact>& elementFacts();
// Whether elements of class `cls` have fact f in a grammar of `space3d`.
bool hasFact(const ElementFact& f, ir::ElemClass cls, bool space3d);

// The fact `name` of an element of class `cls`, or null.
const ElementFact* findElementFact(const std::string& name, ir::ElemClass cls, bool space3d);
// When elements of class `cls` have fact `name` only in the other space
// (`normal` in 2D, `signed_area` in 3D): the error that says which space has
// it; else empty.
std::string otherSpaceFact(const std::string& name, ir::ElemClass cls, bool space3d);

}  // namespace g2d::sema
