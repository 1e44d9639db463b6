#include "sema/builtins.hpp"

#include <map>

namespace g2d::sema {

using ir::Builtin;
using ir::Type;
using ir::TypeKind;

namespace {

const Type I = ir::kIntType;
const Type F = ir::kFloatType;
const Type B = ir::kBoolType;
const Type S = ir::kStringType;
const Type V = ir::kVec2Type;
const Type V3 = ir::kVec3Type;

struct Overload {
    Builtin builtin;
    std::vector<Type> params;
    Type result;
};

// Fixed-signature functions. Numeric parameters declared float accept int.
const std::map<std::string, std::vector<Overload>>& fixedOverloads() {
    static const std::map<std::string, std::vector<Overload>> table = {
        {"sin", {{Builtin::Sin, {F}, F}}},
        {"cos", {{Builtin::Cos, {F}, F}}},
        {"tan", {{Builtin::Tan, {F}, F}}},
        {"asin", {{Builtin::Asin, {F}, F}}},
        {"acos", {{Builtin::Acos, {F}, F}}},
        {"atan", {{Builtin::Atan, {F}, F}}},
        {"atan2", {{Builtin::Atan2, {F, F}, F}}},
        {"sqrt", {{Builtin::Sqrt, {F}, F}}},
        {"exp", {{Builtin::Exp, {F}, F}}},
        {"log", {{Builtin::Log, {F}, F}}},
        {"pow", {{Builtin::Pow, {F, F}, F}}},
        {"hypot", {{Builtin::Hypot, {F, F}, F}}},
        {"floor", {{Builtin::Floor, {F}, I}}},
        {"ceil", {{Builtin::Ceil, {F}, I}}},
        {"round", {{Builtin::Round, {F}, I}}},
        {"radians", {{Builtin::Radians, {F}, F}}},
        {"degrees", {{Builtin::Degrees, {F}, F}}},
        {"abs", {{Builtin::Abs, {I}, I}, {Builtin::Abs, {F}, F}}},
        {"sign", {{Builtin::Sign, {I}, I}, {Builtin::Sign, {F}, F}}},
        {"clamp", {{Builtin::Clamp, {I, I, I}, I}, {Builtin::Clamp, {F, F, F}, F}}},
        {"smoothstep", {{Builtin::Smoothstep, {F, F, F}, F}}},
        {"vec2", {{Builtin::MakeVec2, {F, F}, V}}},
        {"vec3", {{Builtin::MakeVec3, {F, F, F}, V3}}},
        {"dot", {{Builtin::Dot, {V, V}, F}, {Builtin::Dot3, {V3, V3}, F}}},
        {"cross", {{Builtin::Cross, {V, V}, F}, {Builtin::Cross3, {V3, V3}, V3}}},
        {"length", {{Builtin::Length, {V}, F}, {Builtin::Length3, {V3}, F}}},
        {"distance", {{Builtin::Distance, {V, V}, F}, {Builtin::Distance3, {V3, V3}, F}}},
        {"normalize", {{Builtin::Normalize, {V}, V}, {Builtin::Normalize3, {V3}, V3}}},
        {"perp_left", {{Builtin::PerpLeft, {V}, V}}},
        {"perp_right", {{Builtin::PerpRight, {V}, V}}},
        {"rotate", {{Builtin::Rotate, {V, F}, V}, {Builtin::RotateAround, {V, F, V}, V}, {Builtin::RotateAxis, {V3, V3, F}, V3}}},
        {"angle", {{Builtin::Angle, {V}, F}, {Builtin::AngleBetween, {V, V}, F}}},
        {"lerp", {{Builtin::Lerp, {F, F, F}, F}, {Builtin::Lerp, {V, V, F}, V}, {Builtin::Lerp3, {V3, V3, F}, V3}}},
        {"int", {{Builtin::ToInt, {I}, I}, {Builtin::ToInt, {F}, I}, {Builtin::ToInt, {B}, I},
                 {Builtin::ToInt, {S}, I}}},
        {"float", {{Builtin::ToFloat, {F}, F}, {Builtin::ToFloat, {S}, F}, {Builtin::ToFloat, {B}, F}}},
        {"random", {{Builtin::Random, {}, F}}},
        {"uniform", {{Builtin::Uniform, {F, F}, F}}},
        {"randint", {{Builtin::RandInt, {I, I}, I}}},
        {"normal", {{Builtin::Normal, {F, F}, F}}},
    };
    return table;
}

bool accepts(const Type& param, const Type& arg) {
    return param == arg || (param.kind == TypeKind::Float && arg.kind == TypeKind::Int);
}

std::string describe(const std::vector<Type>& ts, const ir::Program& prog) {
    std::string out = "(";
    for (std::size_t i = 0; i < ts.size(); ++i) out += (i ? ", " : "") + ir::typeName(ts[i], prog);
    return out + ")";
}

}  // namespace

const std::vector<BuiltinInfo>& builtinFunctions() {
    static const std::vector<BuiltinInfo> list = {
        {"sin", 1, 1, Builtin::Sin, "sin(x: float) -> float"},
        {"cos", 1, 1, Builtin::Cos, "cos(x: float) -> float"},
        {"tan", 1, 1, Builtin::Tan, "tan(x: float) -> float"},
        {"asin", 1, 1, Builtin::Asin, "asin(x: float) -> float"},
        {"acos", 1, 1, Builtin::Acos, "acos(x: float) -> float"},
        {"atan", 1, 1, Builtin::Atan, "atan(x: float) -> float"},
        {"atan2", 2, 2, Builtin::Atan2, "atan2(y: float, x: float) -> float"},
        {"sqrt", 1, 1, Builtin::Sqrt, "sqrt(x: float) -> float"},
        {"exp", 1, 1, Builtin::Exp, "exp(x: float) -> float"},
        {"log", 1, 1, Builtin::Log, "log(x: float) -> float"},
        {"pow", 2, 2, Builtin::Pow, "pow(x: float, y: float) -> float"},
        {"hypot", 2, 2, Builtin::Hypot, "hypot(x: float, y: float) -> float"},
        {"floor", 1, 1, Builtin::Floor, "floor(x: float) -> int"},
        {"ceil", 1, 1, Builtin::Ceil, "ceil(x: float) -> int"},
        {"round", 1, 1, Builtin::Round, "round(x: float) -> int"},
        {"radians", 1, 1, Builtin::Radians, "radians(degrees: float) -> float"},
        {"degrees", 1, 1, Builtin::Degrees, "degrees(radians: float) -> float"},
        {"abs", 1, 1, Builtin::Abs, "abs(x: int|float)"},
        {"sign", 1, 1, Builtin::Sign, "sign(x: int|float)"},
        {"clamp", 3, 3, Builtin::Clamp, "clamp(x, lo, hi: int|float)"},
        {"smoothstep", 3, 3, Builtin::Smoothstep, "smoothstep(edge0, edge1, x: float) -> float"},
        {"min", 2, -1, Builtin::Min, "min(a, b, ...: int|float)"},
        {"max", 2, -1, Builtin::Max, "max(a, b, ...: int|float)"},
        {"vec2", 2, 2, Builtin::MakeVec2, "vec2(x: float, y: float) -> vec2"},
        {"vec3", 3, 3, Builtin::MakeVec3, "vec3(x: float, y: float, z: float) -> vec3"},
        {"dot", 2, 2, Builtin::Dot, "dot(a, b: vec2|vec3) -> float"},
        {"cross", 2, 2, Builtin::Cross, "cross(a: vec2, b: vec2) -> float, cross(a: vec3, b: vec3) -> vec3"},
        {"length", 1, 1, Builtin::Length, "length(v: vec2|vec3) -> float"},
        {"distance", 2, 2, Builtin::Distance, "distance(a, b: vec2|vec3) -> float"},
        {"normalize", 1, 1, Builtin::Normalize, "normalize(v: vec2|vec3) -> the same type"},
        {"perp_left", 1, 1, Builtin::PerpLeft, "perp_left(v: vec2) -> vec2"},
        {"perp_right", 1, 1, Builtin::PerpRight, "perp_right(v: vec2) -> vec2"},
        {"rotate", 2, 3, Builtin::Rotate, "rotate(v: vec2, angle: float[, centre: vec2]) -> vec2, rotate(v: vec3, axis: vec3, angle: float) -> vec3"},
        {"angle", 1, 2, Builtin::Angle, "angle(v: vec2) -> float, angle(from: vec2, to: vec2) -> float"},
        {"lerp", 3, 3, Builtin::Lerp, "lerp(a, b: float|vec2|vec3, t: float)"},
        {"int", 1, 1, Builtin::ToInt, "int(x: float|bool|string) -> int"},
        {"float", 1, 1, Builtin::ToFloat, "float(x: int|bool|string) -> float"},
        {"str", 1, 1, Builtin::ToStr, "str(x) -> string"},
        {"format", 1, -1, Builtin::Format, "format(template: string, values...) -> string"},
        {"random", 0, 0, Builtin::Random, "random() -> float"},
        {"uniform", 2, 2, Builtin::Uniform, "uniform(a: float, b: float) -> float"},
        {"randint", 2, 2, Builtin::RandInt, "randint(lo: int, hi: int) -> int"},
        {"choice", 1, -1, Builtin::Choice, "choice(a, b, ...) -> the arguments' type"},
        {"normal", 2, 2, Builtin::Normal, "normal(mean: float, stddev: float) -> float"},
    };
    return list;
}

bool drawsRandom(const BuiltinInfo& b) { return rt::builtinEntry(b.builtin).drawsRandom; }

const BuiltinInfo* findBuiltin(const std::string& name) {
    for (const auto& b : builtinFunctions())
        if (b.name == name) return &b;
    return nullptr;
}

std::variant<BuiltinResolution, BuiltinError> resolveBuiltin(const std::string& name,
                                                             const std::vector<Type>& args,
                                                             const ir::Program& prog) {
    const BuiltinInfo* info = findBuiltin(name);
    if (!info) return BuiltinError{"unknown function `" + name + "`"};
    const int n = static_cast<int>(args.size());
    if (n < info->minArgs || (info->maxArgs >= 0 && n > info->maxArgs)) {
        std::string expected = info->maxArgs < 0 ? "at least " + std::to_string(info->minArgs)
                               : info->minArgs == info->maxArgs
                                   ? std::to_string(info->minArgs)
                                   : std::to_string(info->minArgs) + " to " + std::to_string(info->maxArgs);
        return BuiltinError{"`" + name + "` takes " + expected + " argument" +
                            (expected == "1" ? "" : "s") + ", got " + std::to_string(n) + " (" +
                            info->signature + ")"};
    }
    // Variadic and generic functions.
    if (name == "min" || name == "max") {
        bool allInt = true;
        for (int i = 0; i < n; ++i) {
            if (!args[i].isNumeric())
                return BuiltinError{"`" + name + "` needs numbers, argument " + std::to_string(i + 1) + " is " +
                                    ir::typeName(args[i], prog), i};
            allInt = allInt && args[i].kind == TypeKind::Int;
        }
        Type t = allInt ? I : F;
        return BuiltinResolution{name == "min" ? Builtin::Min : Builtin::Max, std::vector<Type>(n, t), t};
    }
    if (name == "str") {
        if (args[0].kind == TypeKind::Void) return BuiltinError{"`str` cannot convert a value of no type", 0};
        return BuiltinResolution{Builtin::ToStr, {args[0]}, S};
    }
    if (name == "format") {
        if (args[0].kind != TypeKind::String)
            return BuiltinError{"`format` needs a template string first, got " + ir::typeName(args[0], prog), 0};
        return BuiltinResolution{Builtin::Format, args, S};
    }
    if (name == "choice") {
        Type t = args[0];
        for (int i = 1; i < n; ++i) {
            if (args[i] == t) continue;
            if (t.isNumeric() && args[i].isNumeric()) { t = F; continue; }
            return BuiltinError{"`choice` needs arguments of one type: argument 1 is " + ir::typeName(args[0], prog) +
                                ", argument " + std::to_string(i + 1) + " is " + ir::typeName(args[i], prog), i};
        }
        return BuiltinResolution{Builtin::Choice, std::vector<Type>(n, t), t};
    }
    const auto& overloads = fixedOverloads().at(name);
    // Exact matches first, so that abs(int) stays int.
    for (const auto& o : overloads)
        if (o.params == args) return BuiltinResolution{o.builtin, o.params, o.result};
    for (const auto& o : overloads) {
        if (o.params.size() != args.size()) continue;
        bool ok = true;
        for (std::size_t i = 0; i < args.size() && ok; ++i) ok = accepts(o.params[i], args[i]);
        if (ok) return BuiltinResolution{o.builtin, o.params, o.result};
    }
    // Point at the first argument that fits no overload of this arity.
    for (const auto& o : overloads) {
        if (o.params.size() != args.size()) continue;
        for (std::size_t i = 0; i < args.size(); ++i)
            if (!accepts(o.params[i], args[i]) && overloads.size() == 1)
                return BuiltinError{"argument " + std::to_string(i + 1) + " of `" + name + "` must be " +
                                    ir::typeName(o.params[i], prog) + ", got " + ir::typeName(args[i], prog) +
                                    " (" + info->signature + ")",
                                    static_cast<int>(i)};
    }
    return BuiltinError{"no version of `" + name + "` takes " + describe(args, prog) + " (" + info->signature + ")"};
}

}  // namespace g2d::sema
