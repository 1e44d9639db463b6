#include "ir/ir.hpp"

namespace g2d::ir {

std::string typeName(const Type& t, const Program& p) {
    switch (t.kind) {
    case TypeKind::Int: return "int";
    case TypeKind::Float: return "float";
    case TypeKind::Bool: return "bool";
    case TypeKind::String: return "string";
    case TypeKind::Vec2: return "vec2";
    case TypeKind::Void: return "void";
    case TypeKind::Enum:
        if (t.enumId >= 0 && static_cast<std::size_t>(t.enumId) < p.enums.size()) return p.enums[t.enumId].name;
        return "enum";
    }
    return "?";
}

}  // namespace g2d::ir
