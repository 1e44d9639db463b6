#pragma once
// The language's checked operations on typed values: integer overflow,
// division by zero, non-finite results and bad conversions throw OpError.
// The constant folder, the interpreter and generated code all call these, so
// they agree to the bit and fail with the same words.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "g2d/value.hpp"
#include "g2d/vec_math.hpp"

namespace g2d::rt {

class OpError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The failures, out of line so that the checks below inline to a compare
// and a rarely taken branch (they run for every arithmetic operation).
[[noreturn]] void throwOverflow();
[[noreturn]] void throwDivisionByZero();
[[noreturn]] void throwNonFinite(double x);
[[noreturn]] void throwNonFiniteVec();

inline long long addInt(long long a, long long b) {
    long long r;
    if (__builtin_add_overflow(a, b, &r)) throwOverflow();
    return r;
}
inline long long subInt(long long a, long long b) {
    long long r;
    if (__builtin_sub_overflow(a, b, &r)) throwOverflow();
    return r;
}
inline long long mulInt(long long a, long long b) {
    long long r;
    if (__builtin_mul_overflow(a, b, &r)) throwOverflow();
    return r;
}
long long modInt(long long a, long long b);     // floored; the sign follows b
inline long long negInt(long long a) {
    if (a == (-9223372036854775807LL - 1)) throwOverflow();
    return -a;
}
inline long long absInt(long long a) { return a < 0 ? negInt(a) : a; }

inline double finite(double x) {                // throws on NaN or infinity
    if (!std::isfinite(x)) throwNonFinite(x);
    return x;
}
inline vec2 finite(vec2 v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) throwNonFiniteVec();
    return v;
}
inline vec3 finite(vec3 v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) throwNonFiniteVec();
    return v;
}
// A position register's value (a vec2, or a vec3 in 3D) has finite coordinates.
inline bool isFinitePosition(vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }
inline bool isFinitePosition(vec3 p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
bool isFinitePosition(const Value& v);
inline double divFloat(double a, double b) {
    if (b == 0) throwDivisionByZero();
    return finite(a / b);
}
double modFloat(double a, double b);            // floored
inline vec2 divVec(vec2 v, double s) {
    if (s == 0) throwDivisionByZero();
    return finite(v / s);
}
inline vec3 divVec(vec3 v, double s) {
    if (s == 0) throwDivisionByZero();
    return finite(v / s);
}

// A daughter's weight, when a parameter gives it: positive and finite.
double checkedWeight(double w);
// A daughter's weight read from the match: finite and not negative (0: the
// daughter is not chosen for this match).
double checkedMatchWeight(double w);
// Some daughter of a match-weighted rule must weigh more than 0.
void checkSomeWeight(const std::vector<double>& weights);
// A merge tolerance (`merge within`), when a parameter gives it: finite, not negative.
double checkedMergeTolerance(double t);
// `layout angles`' cost (finite) and temperature (positive, finite).
double checkedCost(double c);
double checkedTemperature(double t);

long long floatToInt(double x);                 // truncation; throws when out of range
long long floorToInt(double x);
long long ceilToInt(double x);
long long roundToInt(double x);                 // halves away from zero
long long parseInt(const std::string& s);       // int("12")
double parseFloat(const std::string& s);        // float("2.5")

// `{}` and `{:.N}` placeholders, filled with already printed values;
// `{{`/`}}` are literal braces. `decimals[i]` is N for `{:.N}`, -1 for `{}`.
struct FormatHole {
    std::string text;                           // the value as `{}` prints it
    double number = 0;                          // for `{:.N}`: the number (x for vectors)
    double number2 = 0;                         // y for vectors
    double number3 = 0;                         // z for 3D vectors
    int kind = 0;                               // 0 text, 1 number, 2 vec2, 3 vec3
};
std::string formatTemplate(const std::string& templ, const FormatHole* holes, std::size_t count);
// How a value fills a hole: printed as str() prints it; numbers and vectors
// also as numbers. (An enum value fills one with its name, which the back
// end knows: FormatHole{name}.)
FormatHole formatHole(const Value& v);

}  // namespace g2d::rt
