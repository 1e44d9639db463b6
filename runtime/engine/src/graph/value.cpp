#include "g2d/value.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace g2d::rt {

std::string formatNumber(double x) {
    if (x == 0) return "0";
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, res.ptr);
}

std::string formatFixed(double x, int decimals) {
    if (decimals < 0) decimals = 0;
    if (decimals > 17) decimals = 17;
    char buf[512];
    auto res = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::fixed, decimals);
    if (res.ec != std::errc()) return formatNumber(x);
    std::string s(buf, res.ptr);
    // "-0.000" is zero: print it without the sign.
    if (s.size() > 1 && s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
    return s;
}

std::string toString(const Value& v) {
    if (auto* i = std::get_if<long long>(&v)) return std::to_string(*i);
    if (auto* d = std::get_if<double>(&v)) return formatNumber(*d);
    if (auto* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
    if (auto* s = std::get_if<std::string>(&v)) return *s;
    if (auto* p = std::get_if<vec2>(&v)) return "(" + formatNumber(p->x) + ", " + formatNumber(p->y) + ")";
    if (auto* p = std::get_if<vec3>(&v))
        return "(" + formatNumber(p->x) + ", " + formatNumber(p->y) + ", " + formatNumber(p->z) + ")";
    return "enum";
}

}  // namespace g2d::rt
