#pragma once
// The language's built-in functions, each defined once. The interpreter and
// the constant folder call them through callBuiltin(); generated code calls
// them by the names builtinEntry() gives. So a fold, a run and a compiled run
// give the same bits and fail with the same words (rt::OpError).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "g2d/ops.hpp"
#include "g2d/rng.hpp"
#include "g2d/value.hpp"
#include "g2d/vec_math.hpp"

namespace g2d::rt {

// Every built-in once: its id, its function in namespace fn (below), how it
// is called (BuiltinCall), whether it can fail and whether it draws from the
// run's generator. The enum and the table
// (builtinEntry) are both made from this list, so they cannot disagree.
#define G2D_BUILTINS(X)                               \
    /* math */                                        \
    X(Sin, sin, Pure, true, false)                    \
    X(Cos, cos, Pure, true, false)                    \
    X(Tan, tan, Pure, true, false)                    \
    X(Asin, asin, Pure, true, false)                  \
    X(Acos, acos, Pure, true, false)                  \
    X(Atan, atan, Pure, true, false)                  \
    X(Atan2, atan2, Pure, true, false)                \
    X(Sqrt, sqrt, Pure, true, false)                  \
    X(Abs, abs, Pure, true, false)                    \
    X(Min, min, Variadic, false, false)               \
    X(Max, max, Variadic, false, false)               \
    X(Floor, floor, Pure, true, false)                \
    X(Ceil, ceil, Pure, true, false)                  \
    X(Round, round, Pure, true, false)                \
    X(Pow, pow, Pure, true, false)                    \
    X(Exp, exp, Pure, true, false)                    \
    X(Log, log, Pure, true, false)                    \
    X(Clamp, clamp, Pure, false, false)               \
    X(Sign, sign, Pure, false, false)                 \
    X(Radians, radians, Pure, true, false)            \
    X(Degrees, degrees, Pure, true, false)            \
    X(Hypot, hypot, Pure, true, false)                \
    X(Smoothstep, smoothstep, Pure, true, false)      \
    /* vectors */                                     \
    X(MakeVec2, makeVec2, Pure, false, false)         \
    X(Dot, dot, Pure, true, false)                    \
    X(Cross, cross, Pure, true, false)                \
    X(Length, length, Pure, true, false)              \
    X(Distance, distance, Pure, true, false)          \
    X(Normalize, normalize, Pure, false, false)       \
    X(PerpLeft, perpLeft, Pure, false, false)         \
    X(PerpRight, perpRight, Pure, false, false)       \
    X(Rotate, rotate, Pure, true, false)              \
    X(RotateAround, rotateAround, Pure, true, false)  \
    X(Angle, angle, Pure, false, false)               \
    X(AngleBetween, angleBetween, Pure, true, false)  \
    X(Lerp, lerp, Pure, true, false)                  \
    X(MakeVec3, makeVec3, Pure, false, false)         \
    X(Dot3, dot, Pure, true, false)                   \
    X(Cross3, cross, Pure, true, false)               \
    X(Length3, length, Pure, true, false)             \
    X(Distance3, distance, Pure, true, false)         \
    X(Normalize3, normalize, Pure, false, false)      \
    X(Lerp3, lerp, Pure, true, false)                 \
    X(RotateAxis, rotateAxis, Pure, true, false)      \
    /* conversions and strings */                     \
    X(ToInt, toInt, Pure, true, false)                \
    X(ToFloat, toFloat, Pure, true, false)            \
    X(ToStr, str, Special, false, false)              \
    X(Format, format, Special, true, false)           \
    /* randomness (drawn from the run's generator) */ \
    X(Random, random, Random, false, true)            \
    X(Uniform, uniform, Random, true, true)           \
    X(RandInt, randint, Random, true, true)           \
    X(Choice, choice, Special, false, true)           \
    X(Normal, normal, Random, true, true)

enum class Builtin {
#define G2D_BUILTIN_ID(id, fn, call, fails, draws) id,
    G2D_BUILTINS(G2D_BUILTIN_ID)
#undef G2D_BUILTIN_ID
};


// How each built-in is reached.
enum class BuiltinCall {
    Pure,      // fn::NAME(args...): a function of its arguments alone
    Random,    // fn::NAME(rng, args...): draws from the run's generator
    Variadic,  // fn::NAME folded over the arguments, left to right (min, max)
    Special,   // str, format, choice: the back ends build their arguments themselves
};


struct BuiltinEntry {
    Builtin id;
    const char* cppName;   // in namespace g2d::rt::fn
    BuiltinCall call;
    bool mayFail;          // can throw OpError (generated code records the call's place first)
    bool drawsRandom;      // reads the run's generator (never folded; a constant using it is drawn per run)
};

// Indexed by Builtin.
const BuiltinEntry& builtinEntry(Builtin id);

// Calls a Pure, Random or Variadic built-in on values of its parameter types
// (`rng` may be null when no random built-in is called). Throws OpError.
Value callBuiltin(Builtin id, const Value* args, std::size_t count, Rng* rng);

namespace fn {

inline double sin(double x) { return finite(std::sin(x)); }
inline double cos(double x) { return finite(std::cos(x)); }
inline double tan(double x) { return finite(std::tan(x)); }
inline double asin(double x) { return finite(std::asin(x)); }
inline double acos(double x) { return finite(std::acos(x)); }
inline double atan(double x) { return finite(std::atan(x)); }
inline double atan2(double y, double x) { return finite(std::atan2(y, x)); }
inline double sqrt(double x) { return finite(std::sqrt(x)); }
inline double exp(double x) { return finite(std::exp(x)); }
inline double log(double x) { return finite(std::log(x)); }
inline double pow(double x, double y) { return finite(std::pow(x, y)); }
inline double hypot(double x, double y) { return finite(std::hypot(x, y)); }
inline long long floor(double x) { return floorToInt(x); }
inline long long ceil(double x) { return ceilToInt(x); }
inline long long round(double x) { return roundToInt(x); }
inline double radians(double x) { return finite(x * 3.141592653589793 / 180.0); }
inline double degrees(double x) { return finite(x * 180.0 / 3.141592653589793); }
inline long long abs(long long x) { return absInt(x); }
inline double abs(double x) { return std::fabs(x); }
inline long long sign(long long x) { return (x > 0) - (x < 0); }
inline double sign(double x) { return static_cast<double>((x > 0) - (x < 0)); }
// clamp(x, lo, hi) = min(max(x, lo), hi): hi when lo > hi.
inline long long clamp(long long x, long long lo, long long hi) { return std::min(std::max(x, lo), hi); }
inline double clamp(double x, double lo, double hi) { return std::min(std::max(x, lo), hi); }
// 0 up to edge0, 1 from edge1 on, and the cubic 3t² − 2t³ between (t the
// position of x from edge0 to edge1; edge1 < edge0 runs the other way).
double smoothstep(double edge0, double edge1, double x);
// Ties keep the earlier argument.
inline long long min(long long a, long long b) { return b < a ? b : a; }
inline double min(double a, double b) { return b < a ? b : a; }
inline long long max(long long a, long long b) { return b > a ? b : a; }
inline double max(double a, double b) { return b > a ? b : a; }

inline vec2 makeVec2(double x, double y) { return vec2(x, y); }
inline double dot(vec2 a, vec2 b) { return finite(rt::dot(a, b)); }
inline double cross(vec2 a, vec2 b) { return finite(rt::cross(a, b)); }
inline double length(vec2 v) { return finite(rt::length(v)); }
inline double distance(vec2 a, vec2 b) { return finite(rt::distance(a, b)); }
inline vec2 normalize(vec2 v) { return rt::normalize(v); }   // the zero vector stays zero
inline vec2 perpLeft(vec2 v) { return rt::perpLeft(v); }
inline vec2 perpRight(vec2 v) { return rt::perpRight(v); }
inline vec2 rotate(vec2 v, double radians) { return finite(rt::rotate(v, radians)); }
inline vec2 rotateAround(vec2 v, double radians, vec2 centre) { return finite(rt::rotateAround(v, radians, centre)); }
inline double angle(vec2 v) { return rt::angle(v); }
inline double angleBetween(vec2 a, vec2 b) { return finite(rt::angleBetween(a, b)); }
inline double lerp(double a, double b, double t) { return finite(rt::lerp(a, b, t)); }
inline vec2 lerp(vec2 a, vec2 b, double t) { return finite(rt::lerp(a, b, t)); }

inline vec3 makeVec3(double x, double y, double z) { return vec3(x, y, z); }
inline double dot(vec3 a, vec3 b) { return finite(rt::dot(a, b)); }
inline vec3 cross(vec3 a, vec3 b) { return finite(rt::cross(a, b)); }
inline double length(vec3 v) { return finite(rt::length(v)); }
inline double distance(vec3 a, vec3 b) { return finite(rt::distance(a, b)); }
inline vec3 normalize(vec3 v) { return rt::normalize(v); }
inline vec3 lerp(vec3 a, vec3 b, double t) { return finite(rt::lerp(a, b, t)); }
inline vec3 rotateAxis(vec3 v, vec3 axis, double radians) { return finite(rt::rotateAxis(v, axis, radians)); }

inline long long toInt(long long v) { return v; }
inline long long toInt(double v) { return floatToInt(v); }
inline long long toInt(bool v) { return v ? 1 : 0; }
inline long long toInt(const std::string& v) { return parseInt(v); }
inline double toFloat(long long v) { return static_cast<double>(v); }
inline double toFloat(double v) { return v; }
inline double toFloat(bool v) { return v ? 1.0 : 0.0; }
inline double toFloat(const std::string& v) { return parseFloat(v); }

inline double random(Rng& rng) { return rng.unit(); }
inline double uniform(Rng& rng, double a, double b) { return finite(rng.uniform(a, b)); }
long long randint(Rng& rng, long long lo, long long hi);   // throws on an empty range
inline double normal(Rng& rng, double mean, double stddev) { return finite(rng.normal(mean, stddev)); }
// choice(a, b, …): which of its `count` arguments it returns.
inline std::size_t choiceIndex(Rng& rng, std::size_t count) { return static_cast<std::size_t>(rng.below(count)); }

}  // namespace fn

}  // namespace g2d::rt
