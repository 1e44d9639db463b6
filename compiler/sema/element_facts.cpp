#include "sema/element_facts.hpp"

#include <string_view>

namespace g2d::sema {

const std::vector<ElementFact>& elementFacts() {
    static const std::vector<ElementFact> facts = [] {
        std::vector<ElementFact> out;
        std::size_t count = 0;
        const rt::ElementFactEntry* entries = rt::elementFactEntries(count);
        for (std::size_t i = 0; i < count; ++i) {
            const auto& e = entries[i];
            const std::string_view t = e.typeName;
            const ir::TypeKind type = t == "vec2"    ? ir::TypeKind::Vec2
                                      : t == "vec3"  ? ir::TypeKind::Vec3
                                      : t == "float" ? ir::TypeKind::Float
                                                     : ir::TypeKind::Int;
            out.push_back(ElementFact{e.name, e.id, type, e.classes, e.spaces, std::string(e.typeName) + ": " + e.meaning});
        }
        return out;
    }();
    return facts;
}

bool hasFact(const ElementFact& f, ir::ElemClass cls, bool space3d) {
    return (f.classes & rt::classBit(cls)) != 0 && (f.spaces & (space3d ? rt::kIn3d : rt::kIn2d)) != 0;
}

const ElementFact* findElementFact(const std::string& name, ir::ElemClass cls, bool space3d) {
    for (const auto& f : elementFacts())
        if (name == f.name && hasFact(f, cls, space3d)) return &f;
    return nullptr;
}

std::string otherSpaceFact(const std::string& name, ir::ElemClass cls, bool space3d) {
    if (findElementFact(name, cls, space3d) || !findElementFact(name, cls, !space3d)) return {};
    return std::string(rt::elemClassName(cls)) + " fact `" + name + "` exists only in " +
           (space3d ? "2D grammars (this one is `space 3d;`)" : "3D grammars (`space 3d;`)");
}

}  // namespace g2d::sema
