#include "g2d/ops.hpp"

#include <charconv>
#include <climits>
#include <cmath>

#include "g2d/value.hpp"

namespace g2d::rt {

void throwOverflow() { throw OpError("integer overflow"); }
void throwDivisionByZero() { throw OpError("division by zero"); }
void throwNonFinite(double x) {
    throw OpError(std::isnan(x) ? "the result is not a number (NaN)" : "the result is infinite");
}
void throwNonFiniteVec() { throw OpError("the result is not a finite vector"); }

namespace {
[[noreturn]] void overflow() { throwOverflow(); }
[[noreturn]] void divisionByZero() { throwDivisionByZero(); }
}  // namespace

long long modInt(long long a, long long b) {
    if (b == 0) divisionByZero();
    if (a == LLONG_MIN && b == -1) overflow();
    return imodFloor(a, b);
}

double modFloat(double a, double b) {
    if (b == 0) divisionByZero();
    return finite(fmodFloor(a, b));
}

double checkedWeight(double w) {
    if (!(w > 0) || !std::isfinite(w)) throw OpError("a weight must be positive, but this is " + formatNumber(w));
    return w;
}

double checkedMatchWeight(double w) {
    if (!(w >= 0) || !std::isfinite(w))
        throw OpError("a weight must be 0 or more, but this is " + formatNumber(w) + " for this match");
    return w;
}

void checkSomeWeight(const std::vector<double>& weights) {
    for (double w : weights)
        if (w > 0) return;
    throw OpError("every daughter's weight is 0 for this match: a match that must not be rewritten belongs in "
                  "the match's conditions (`where`)");
}

double checkedMergeTolerance(double t) {
    if (!(t >= 0) || !std::isfinite(t)) throw OpError("a merge tolerance must be finite and not negative, but this is " + formatNumber(t));
    return t;
}

double checkedCost(double c) {
    if (!std::isfinite(c)) throw OpError("the cost must be a finite number, but this is " + formatNumber(c));
    return c;
}

double checkedTemperature(double t) {
    if (!(t > 0) || !std::isfinite(t)) throw OpError("the temperature must be positive and finite, but this is " + formatNumber(t));
    return t;
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

bool isFinitePosition(const Value& v) {
    if (const auto* p = std::get_if<vec3>(&v)) return isFinitePosition(*p);
    return isFinitePosition(std::get<vec2>(v));
}

FormatHole formatHole(const Value& v) {
    FormatHole h;
    h.text = toString(v);
    if (const auto* d = std::get_if<double>(&v)) {
        h.kind = 1;
        h.number = *d;
    } else if (const auto* n = std::get_if<long long>(&v)) {
        h.kind = 1;
        h.number = static_cast<double>(*n);
    } else if (const auto* p = std::get_if<vec2>(&v)) {
        h.kind = 2;
        h.number = p->x;
        h.number2 = p->y;
    } else if (const auto* q = std::get_if<vec3>(&v)) {
        h.kind = 3;
        h.number = q->x;
        h.number2 = q->y;
        h.number3 = q->z;
    }
    return h;
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
            if (h.kind >= 2) out += " " + formatFixed(h.number2, decimals);
            if (h.kind == 3) out += " " + formatFixed(h.number3, decimals);
        }
        i = close;
    }
    return out;
}

}  // namespace g2d::rt
