#include "g2d/builtins.hpp"

#include <cmath>
#include <stdexcept>

namespace g2d::rt {

namespace {

using B = Builtin;
using C = BuiltinCall;

constexpr BuiltinEntry kTable[] = {
#define G2D_BUILTIN_ROW(id, fn, call, fails, draws) {B::id, #fn, C::call, fails, draws},
    G2D_BUILTINS(G2D_BUILTIN_ROW)
#undef G2D_BUILTIN_ROW
};

long long I(const Value& v) { return std::get<long long>(v); }
double F(const Value& v) { return std::get<double>(v); }
vec2 V(const Value& v) { return std::get<vec2>(v); }
vec3 V3(const Value& v) { return std::get<vec3>(v); }
bool isInt(const Value& v) { return std::holds_alternative<long long>(v); }

// The conversions take any scalar.
template <class F>
Value convert(const Value& v, F&& to) {
    return std::visit(
        [&](const auto& x) -> Value {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, long long> || std::is_same_v<T, double> || std::is_same_v<T, bool> ||
                          std::is_same_v<T, std::string>)
                return to(x);
            else
                throw std::logic_error("a conversion built-in called on a vector or an enum");
        },
        v);
}

}  // namespace

const BuiltinEntry& builtinEntry(Builtin id) { return kTable[static_cast<std::size_t>(id)]; }

namespace fn {
long long randint(Rng& rng, long long lo, long long hi) {
    if (lo > hi) throw OpError("randint(" + std::to_string(lo) + ", " + std::to_string(hi) + "): empty range");
    return rng.range(lo, hi);
}

double smoothstep(double edge0, double edge1, double x) {
    if (edge0 == edge1) throw OpError("smoothstep(" + formatNumber(edge0) + ", " + formatNumber(edge1) + ", x): the edges are equal");
    double num = x - edge0, den = edge1 - edge0;
    if (!std::isfinite(num) || !std::isfinite(den)) num = x * 0.5 - edge0 * 0.5, den = edge1 * 0.5 - edge0 * 0.5;   // no overflow
    const double t = clamp(num / den, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}
}  // namespace fn

Value callBuiltin(Builtin id, const Value* a, std::size_t n, Rng* rng) {
    auto needRng = [&]() -> Rng& {
        if (!rng) throw std::logic_error("a random built-in called without a generator");
        return *rng;
    };
    switch (id) {
    case B::Sin: return fn::sin(F(a[0]));
    case B::Cos: return fn::cos(F(a[0]));
    case B::Tan: return fn::tan(F(a[0]));
    case B::Asin: return fn::asin(F(a[0]));
    case B::Acos: return fn::acos(F(a[0]));
    case B::Atan: return fn::atan(F(a[0]));
    case B::Atan2: return fn::atan2(F(a[0]), F(a[1]));
    case B::Sqrt: return fn::sqrt(F(a[0]));
    case B::Exp: return fn::exp(F(a[0]));
    case B::Log: return fn::log(F(a[0]));
    case B::Pow: return fn::pow(F(a[0]), F(a[1]));
    case B::Hypot: return fn::hypot(F(a[0]), F(a[1]));
    case B::Floor: return fn::floor(F(a[0]));
    case B::Ceil: return fn::ceil(F(a[0]));
    case B::Round: return fn::round(F(a[0]));
    case B::Radians: return fn::radians(F(a[0]));
    case B::Degrees: return fn::degrees(F(a[0]));
    case B::Abs: return isInt(a[0]) ? Value{fn::abs(I(a[0]))} : Value{fn::abs(F(a[0]))};
    case B::Sign: return isInt(a[0]) ? Value{fn::sign(I(a[0]))} : Value{fn::sign(F(a[0]))};
    case B::Smoothstep: return fn::smoothstep(F(a[0]), F(a[1]), F(a[2]));
    case B::Clamp:
        return isInt(a[0]) ? Value{fn::clamp(I(a[0]), I(a[1]), I(a[2]))} : Value{fn::clamp(F(a[0]), F(a[1]), F(a[2]))};
    case B::Min:
    case B::Max: {
        Value best = a[0];
        for (std::size_t i = 1; i < n; ++i) {
            if (isInt(best)) best = id == B::Min ? fn::min(I(best), I(a[i])) : fn::max(I(best), I(a[i]));
            else best = id == B::Min ? fn::min(F(best), F(a[i])) : fn::max(F(best), F(a[i]));
        }
        return best;
    }
    case B::MakeVec2: return fn::makeVec2(F(a[0]), F(a[1]));
    case B::Dot: return fn::dot(V(a[0]), V(a[1]));
    case B::Cross: return fn::cross(V(a[0]), V(a[1]));
    case B::Length: return fn::length(V(a[0]));
    case B::Distance: return fn::distance(V(a[0]), V(a[1]));
    case B::Normalize: return fn::normalize(V(a[0]));
    case B::PerpLeft: return fn::perpLeft(V(a[0]));
    case B::PerpRight: return fn::perpRight(V(a[0]));
    case B::Rotate: return fn::rotate(V(a[0]), F(a[1]));
    case B::RotateAround: return fn::rotateAround(V(a[0]), F(a[1]), V(a[2]));
    case B::Angle: return fn::angle(V(a[0]));
    case B::AngleBetween: return fn::angleBetween(V(a[0]), V(a[1]));
    case B::Lerp:
        if (std::holds_alternative<vec2>(a[0])) return fn::lerp(V(a[0]), V(a[1]), F(a[2]));
        return fn::lerp(F(a[0]), F(a[1]), F(a[2]));
    case B::MakeVec3: return fn::makeVec3(F(a[0]), F(a[1]), F(a[2]));
    case B::Dot3: return fn::dot(V3(a[0]), V3(a[1]));
    case B::Cross3: return fn::cross(V3(a[0]), V3(a[1]));
    case B::Length3: return fn::length(V3(a[0]));
    case B::Distance3: return fn::distance(V3(a[0]), V3(a[1]));
    case B::Normalize3: return fn::normalize(V3(a[0]));
    case B::Lerp3: return fn::lerp(V3(a[0]), V3(a[1]), F(a[2]));
    case B::RotateAxis: return fn::rotateAxis(V3(a[0]), V3(a[1]), F(a[2]));
    case B::ToInt: return convert(a[0], [](const auto& x) { return Value{fn::toInt(x)}; });
    case B::ToFloat: return convert(a[0], [](const auto& x) { return Value{fn::toFloat(x)}; });
    case B::Random: return fn::random(needRng());
    case B::Uniform: return fn::uniform(needRng(), F(a[0]), F(a[1]));
    case B::RandInt: return fn::randint(needRng(), I(a[0]), I(a[1]));
    case B::Normal: return fn::normal(needRng(), F(a[0]), F(a[1]));
    case B::ToStr:
    case B::Format:
    case B::Choice: break;
    }
    throw std::logic_error(std::string("callBuiltin: `") + builtinEntry(id).cppName + "` is built by the back ends");
}

}  // namespace g2d::rt
