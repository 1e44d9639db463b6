#include "ir/ir.hpp"

namespace g2d::ir {

std::string typeName(const Type& t, const Program& p) {
    switch (t.kind) {
    case TypeKind::Int: return "int";
    case TypeKind::Float: return "float";
    case TypeKind::Bool: return "bool";
    case TypeKind::String: return "string";
    case TypeKind::Vec2: return "vec2";
    case TypeKind::Vec3: return "vec3";
    case TypeKind::Void: return "void";
    case TypeKind::Enum:
        if (t.enumId >= 0 && static_cast<std::size_t>(t.enumId) < p.enums.size()) return p.enums[t.enumId].name;
        return "enum";
    }
    return "?";
}

std::optional<rt::BinaryOp> binaryOperator(ExprOp op) {
    switch (op) {
    case ExprOp::Add: return rt::BinaryOp::Add;
    case ExprOp::Sub: return rt::BinaryOp::Sub;
    case ExprOp::Mul: return rt::BinaryOp::Mul;
    case ExprOp::Div: return rt::BinaryOp::Div;
    case ExprOp::Mod: return rt::BinaryOp::Mod;
    case ExprOp::Lt: return rt::BinaryOp::Lt;
    case ExprOp::Le: return rt::BinaryOp::Le;
    case ExprOp::Gt: return rt::BinaryOp::Gt;
    case ExprOp::Ge: return rt::BinaryOp::Ge;
    case ExprOp::Eq: return rt::BinaryOp::Eq;
    case ExprOp::Ne: return rt::BinaryOp::Ne;
    default: return std::nullopt;
    }
}

rt::Value toRuntime(const Value& v) {
    return std::visit(
        [](const auto& x) -> rt::Value {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, Vec2>) return rt::vec2(x.x, x.y);
            else if constexpr (std::is_same_v<T, Vec3>) return rt::vec3(x.x, x.y, x.z);
            else if constexpr (std::is_same_v<T, EnumValue>) return rt::EnumVal{x.enumId, x.index};
            else return x;
        },
        v);
}

Value fromRuntime(const rt::Value& v) {
    return std::visit(
        [](const auto& x) -> Value {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, rt::vec2>) return Vec2{x.x, x.y};
            else if constexpr (std::is_same_v<T, rt::vec3>) return Vec3{x.x, x.y, x.z};
            else if constexpr (std::is_same_v<T, rt::EnumVal>) return EnumValue{x.enumId, x.index};
            else return x;
        },
        v);
}

bool runsParallel(const Program& p, const Rule& r) {
    const auto prio = p.priorities.find(r.priority);
    return r.parallel || (prio != p.priorities.end() && prio->second.parallel);
}

bool inGeneration(const Program& p, const Rule& r) {
    const auto prio = p.priorities.find(r.priority);
    return prio != p.priorities.end() && prio->second.generation;
}

bool keptEdgeRewired(const Rule& r, const Daughter& d, const DaughterEdge& e) {
    const PatternEdge& me = r.edges[static_cast<std::size_t>(e.motherEdge)];
    return d.nodes[static_cast<std::size_t>(e.src)].motherNode != me.src || d.nodes[static_cast<std::size_t>(e.dst)].motherNode != me.dst;
}

}  // namespace g2d::ir
