// Parses the SVG attribute syntaxes the example reader needs (svg_syntax.hpp).
#include "infer/svg_syntax.hpp"

#include "g2d/css_color.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace g2d::infer::svg {
namespace {

bool isWsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isAlpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

// What is left of the text at `i`, short, for messages.
std::string excerpt(std::string_view s, std::size_t i) {
    if (i >= s.size()) return "the end";
    const std::string_view rest = s.substr(i);
    return "\"" + std::string(rest.substr(0, 16)) + (rest.size() > 16 ? "...\"" : "\"");
}

void skipWsp(std::string_view s, std::size_t& i) {
    while (i < s.size() && isWsp(s[i])) ++i;
}
void skipCommaWsp(std::string_view s, std::size_t& i) {
    skipWsp(s, i);
    if (i < s.size() && s[i] == ',') ++i;
    skipWsp(s, i);
}

// SVG's number grammar, which lets numbers run together ("1-2", ".5.5"), so
// the extent is found by hand; from_chars then converts without the locale.
std::optional<double> scanNumber(std::string_view s, std::size_t& i) {
    std::size_t j = i;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    const std::size_t mantissa = j;
    bool digits = false;
    while (j < s.size() && isDigit(s[j])) ++j, digits = true;
    if (j < s.size() && s[j] == '.') {
        ++j;
        while (j < s.size() && isDigit(s[j])) ++j, digits = true;
    }
    if (!digits) return std::nullopt;
    if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
        std::size_t k = j + 1;
        if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
        const std::size_t exponent = k;
        while (k < s.size() && isDigit(s[k])) ++k;
        if (k > exponent) j = k;   // "1em": the number ends before the unit
    }
    double v = 0;
    const char* first = s.data() + mantissa;
    const char* last = s.data() + j;
    const auto [end, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || end != last || !std::isfinite(v)) return std::nullopt;
    if (s[i] == '-') v = -v;
    i = j;
    return v;
}

double needNumber(std::string_view s, std::size_t& i) {
    if (const auto v = scanNumber(s, i)) return *v;
    throw SyntaxError{"expected a number at " + excerpt(s, i)};
}

// Exact for multiples of 90 degrees, so that drawings turned by right angles
// keep exact coordinates (vertex merging and the tests compare them).
void cosSin(double degrees, double& c, double& s) {
    const double r = std::fmod(std::fmod(degrees, 360.0) + 360.0, 360.0);
    constexpr std::array<std::array<double, 2>, 4> right{{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};
    for (int k = 0; k < 4; ++k)
        if (r == 90.0 * k) {
            c = right[k][0], s = right[k][1];
            return;
        }
    const double rad = r * std::numbers::pi / 180;   // reduced: a huge angle is still an angle
    c = std::cos(rad), s = std::sin(rad);
}

double tangent(const std::string& name, double degrees) {
    const double r = std::fmod(std::fmod(degrees, 180.0) + 180.0, 180.0);
    if (r == 0) return 0;
    if (r == 45) return 1;
    if (r == 135) return -1;
    if (r == 90) {
        char angle[32];
        std::snprintf(angle, sizeof angle, "%.15g", degrees);
        throw SyntaxError{name + "(" + angle + ") has no finite matrix"};
    }
    return std::tan(r * std::numbers::pi / 180);
}

Matrix transformFunction(const std::string& name, const std::vector<double>& v) {
    const std::size_t n = v.size();
    auto takes = [&](std::size_t a, std::size_t b, const char* what) {
        if (n != a && n != b) throw SyntaxError{name + " takes " + what + " numbers, not " + std::to_string(n)};
    };
    if (name == "matrix") {
        takes(6, 6, "6");
        return {v[0], v[1], v[2], v[3], v[4], v[5]};
    }
    if (name == "translate") {
        takes(1, 2, "1 or 2");
        return {1, 0, 0, 1, v[0], n == 2 ? v[1] : 0};
    }
    if (name == "scale") {
        takes(1, 2, "1 or 2");
        return {v[0], 0, 0, n == 2 ? v[1] : v[0], 0, 0};
    }
    if (name == "rotate") {
        takes(1, 3, "1 or 3");
        double c = 1, s = 0;
        cosSin(v[0], c, s);
        const Matrix turn{c, s, -s, c, 0, 0};
        if (n == 1) return turn;
        return Matrix{1, 0, 0, 1, v[1], v[2]} * turn * Matrix{1, 0, 0, 1, -v[1], -v[2]};
    }
    if (name == "skewX") {
        takes(1, 1, "1");
        return {1, 0, tangent(name, v[0]), 1, 0, 0};
    }
    if (name == "skewY") {
        takes(1, 1, "1");
        return {1, tangent(name, v[0]), 0, 1, 0, 0};
    }
    throw SyntaxError{"\"" + name + "\" is not a transform"};
}

}  // namespace

Matrix operator*(const Matrix& m, const Matrix& n) {
    return {m.a * n.a + m.c * n.b, m.b * n.a + m.d * n.b,
            m.a * n.c + m.c * n.d, m.b * n.c + m.d * n.d,
            m.a * n.e + m.c * n.f + m.e, m.b * n.e + m.d * n.f + m.f};
}

std::string_view trim(std::string_view text) {
    while (!text.empty() && isWsp(text.front())) text.remove_prefix(1);
    while (!text.empty() && isWsp(text.back())) text.remove_suffix(1);
    return text;
}

std::optional<double> parseLength(std::string_view text) {
    const std::string_view t = trim(text);
    std::size_t i = 0;
    const auto v = scanNumber(t, i);
    if (!v) return std::nullopt;
    const std::string_view unit = t.substr(i);
    if (!unit.empty() && unit != "px") return std::nullopt;
    return v;
}

std::vector<double> parseNumberList(std::string_view text) {
    std::vector<double> out;
    std::size_t i = 0;
    skipWsp(text, i);
    while (i < text.size()) {
        out.push_back(needNumber(text, i));
        skipCommaWsp(text, i);
    }
    return out;
}

Matrix parseTransform(std::string_view text) {
    Matrix m;
    std::size_t i = 0;
    skipWsp(text, i);
    while (i < text.size()) {
        const std::size_t start = i;
        while (i < text.size() && isAlpha(text[i])) ++i;
        if (i == start) throw SyntaxError{"expected a transform at " + excerpt(text, start)};
        const std::string name(text.substr(start, i - start));
        skipWsp(text, i);
        if (i >= text.size() || text[i] != '(') throw SyntaxError{"expected \"(\" after " + name};
        ++i;
        skipWsp(text, i);
        std::vector<double> args;
        while (i < text.size() && text[i] != ')') {
            args.push_back(needNumber(text, i));
            skipCommaWsp(text, i);
        }
        if (i >= text.size()) throw SyntaxError{"missing \")\" after " + name};
        ++i;
        m = m * transformFunction(name, args);
        for (double entry : {m.a, m.b, m.c, m.d, m.e, m.f})
            if (!std::isfinite(entry)) throw SyntaxError{"the transform overflows at " + name};
        skipCommaWsp(text, i);
    }
    return m;
}

std::vector<Subpath> parsePathData(std::string_view s) {
    std::vector<Subpath> out;
    Subpath cur;
    UserPoint pos, start;
    char cmd = 0;
    auto flush = [&] {
        if (cur.points.size() > 1 || cur.closed) out.push_back(cur);
        cur = {};
    };
    std::size_t i = 0;
    skipWsp(s, i);
    while (i < s.size()) {
        const char c = s[i];
        if (isAlpha(c)) {
            ++i;
            switch (c) {
            case 'M': case 'm': case 'L': case 'l': case 'H': case 'h': case 'V': case 'v': case 'Z': case 'z':
                if (cmd == 0 && c != 'M' && c != 'm') throw SyntaxError{"path data must start with M or m"};
                cmd = c;
                break;
            case 'C': case 'c': case 'S': case 's': case 'Q': case 'q': case 'T': case 't': case 'A': case 'a':
                throw SyntaxError{std::string("the command '") + c +
                                  "' draws a curve: only straight segments (M, L, H, V, Z) are supported"};
            default:
                throw SyntaxError{std::string("'") + c + "' is not a path command"};
            }
            if (lower(cmd) == 'z') {
                if (!cur.points.empty()) cur.closed = true;
                flush();
                pos = start;
                skipWsp(s, i);
                continue;
            }
            skipWsp(s, i);
        } else if (cmd == 0) {
            throw SyntaxError{"path data must start with M or m"};
        } else if (lower(cmd) == 'z') {
            throw SyntaxError{"expected a command at " + excerpt(s, i)};
        }
        const bool relative = cmd >= 'a';
        const char op = lower(cmd);
        UserPoint next = pos;
        if (op == 'm' || op == 'l') {
            const double x = needNumber(s, i);
            skipCommaWsp(s, i);
            const double y = needNumber(s, i);
            next = relative ? UserPoint{pos.x + x, pos.y + y} : UserPoint{x, y};
        } else if (op == 'h') {
            const double x = needNumber(s, i);
            next.x = relative ? pos.x + x : x;
        } else {
            const double y = needNumber(s, i);
            next.y = relative ? pos.y + y : y;
        }
        if (!std::isfinite(next.x) || !std::isfinite(next.y))
            throw SyntaxError{"the relative coordinates add up past any number before " + excerpt(s, i)};
        if (op == 'm') {
            flush();
            start = next;
            cmd = relative ? 'l' : 'L';   // further pairs are linetos
        } else if (cur.points.empty()) {
            cur.points.push_back(pos);     // a subpath after Z starts where the last one did
        }
        cur.points.push_back(next);
        pos = next;
        skipCommaWsp(s, i);
    }
    flush();
    return out;
}

std::optional<std::string> parseColor(std::string_view text) {
    const auto c = rt::cssColor(text);
    if (!c || c->a != 1) return std::nullopt;
    std::string hex = "#";
    for (double v : {c->r, c->g, c->b}) {
        const int b = static_cast<int>(std::lround(v * 255));
        constexpr char digits[] = "0123456789abcdef";
        hex += digits[b / 16];
        hex += digits[b % 16];
    }
    return hex;
}

}  // namespace g2d::infer::svg
