#include "g2d/ops.hpp"

#include <charconv>
#include <climits>
#include <cmath>

#include "g2d/value.hpp"

namespace g2d::rt {

namespace {
[[noreturn]] void overflow() { throw OpError("integer overflow"); }
[[noreturn]] void divisionByZero() { throw OpError("division by zero"); }
}  // namespace

long long addInt(long long a, long long b) {
    long long r;
    if (__builtin_add_overflow(a, b, &r)) overflow();
    return r;
}
long long subInt(long long a, long long b) {
    long long r;
    if (__builtin_sub_overflow(a, b, &r)) overflow();
    return r;
}
long long mulInt(long long a, long long b) {
    long long r;
    if (__builtin_mul_overflow(a, b, &r)) overflow();
    return r;
}
long long modInt(long long a, long long b) {
    if (b == 0) divisionByZero();
    if (a == LLONG_MIN && b == -1) overflow();
    return imodFloor(a, b);
}
long long negInt(long long a) {
    if (a == LLONG_MIN) overflow();
    return -a;
}
long long absInt(long long a) { return a < 0 ? negInt(a) : a; }

double finite(double x) {
    if (!std::isfinite(x)) throw OpError(std::isnan(x) ? "the result is not a number (NaN)" : "the result is infinite");
    return x;
}
vec2 finite(vec2 v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) throw OpError("the result is not a finite vector");
    return v;
}
double divFloat(double a, double b) {
    if (b == 0) divisionByZero();
    return finite(a / b);
}
double modFloat(double a, double b) {
    if (b == 0) divisionByZero();
    return finite(fmodFloor(a, b));
}
vec2 divVec(vec2 v, double s) {
    if (s == 0) divisionByZero();
    return finite(v / s);
}

long long floatToInt(double x) {
    if (!std::isfinite(x) || x >= 9.2233720368547758e18 || x < -9.2233720368547758e18)
        throw OpError("cannot convert " + formatNumber(x) + " to int: out of range");
    return static_cast<long long>(x);
}
long long floorToInt(double x) { return floatToInt(std::floor(x)); }
long long ceilToInt(double x) { return floatToInt(std::ceil(x)); }
long long roundToInt(double x) { return floatToInt(roundHalfAway(x)); }

long long parseInt(const std::string& s) {
    long long v = 0;
    auto res = std::from_chars(s.data(), s.data() + s.size(), v);
    if (res.ec != std::errc() || res.ptr != s.data() + s.size()) throw OpError("int(\"" + s + "\"): not an integer");
    return v;
}

double parseFloat(const std::string& s) {
    double v = 0;
    auto res = std::from_chars(s.data(), s.data() + s.size(), v);
    if (res.ec != std::errc() || res.ptr != s.data() + s.size() || !std::isfinite(v))
        throw OpError("float(\"" + s + "\"): not a number");
    return v;
}

std::string formatTemplate(const std::string& t, const FormatHole* holes, std::size_t count) {
    std::string out;
    std::size_t next = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if ((t[i] == '{' || t[i] == '}') && i + 1 < t.size() && t[i + 1] == t[i]) { out += t[i++]; continue; }
        if (t[i] != '{') { out += t[i]; continue; }
        const std::size_t close = t.find('}', i);
        const std::string spec = t.substr(i + 1, close - i - 1);
        if (next >= count) throw OpError("format: too few values");
        const FormatHole& h = holes[next++];
        if (spec.empty() || h.kind == 0) {
            out += h.text;
        } else {
            const int decimals = std::stoi(spec.substr(2));
            out += formatFixed(h.number, decimals);
            if (h.kind == 2) out += " " + formatFixed(h.number2, decimals);
        }
        i = close;
    }
    return out;
}

}  // namespace g2d::rt
