#include "g2d/svg_extent.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

#include "g2d/svg_element.hpp"
#include "g2d/utf8.hpp"

namespace g2d::rt {

namespace {

// Reads the numbers of path data and point lists: separated by spaces or
// commas, or by nothing before a sign or a second decimal point ("1-2", "1.5.5").
class NumberReader {
public:
    explicit NumberReader(std::string_view s) : s_(s) {}

    void skipSeparators() {
        while (at_ < s_.size() && (s_[at_] == ' ' || s_[at_] == ',' || s_[at_] == '\t' || s_[at_] == '\n' || s_[at_] == '\r'))
            ++at_;
    }
    bool atEnd() {
        skipSeparators();
        return at_ >= s_.size();
    }
    bool atNumber() {
        skipSeparators();
        if (at_ >= s_.size()) return false;
        const char c = s_[at_];
        return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
    }
    std::optional<char> command() {
        skipSeparators();
        if (at_ >= s_.size()) return std::nullopt;
        return s_[at_++];
    }
    std::optional<double> number() {
        if (!atNumber()) return std::nullopt;
        std::size_t end = at_;
        if (s_[end] == '-' || s_[end] == '+') ++end;
        bool dot = false, digits = false;
        for (; end < s_.size(); ++end) {
            const char c = s_[end];
            if (c >= '0' && c <= '9') digits = true;
            else if (c == '.' && !dot) dot = true;
            else break;
        }
        if (digits && end < s_.size() && (s_[end] == 'e' || s_[end] == 'E')) {
            std::size_t e = end + 1;
            if (e < s_.size() && (s_[e] == '-' || s_[e] == '+')) ++e;
            if (e < s_.size() && s_[e] >= '0' && s_[e] <= '9') {
                while (e < s_.size() && s_[e] >= '0' && s_[e] <= '9') ++e;
                end = e;
            }
        }
        if (!digits) return std::nullopt;
        std::size_t from = at_ + (s_[at_] == '+' ? 1 : 0);
        double x = 0;
        const auto r = std::from_chars(s_.data() + from, s_.data() + end, x);
        if (r.ec != std::errc() || !std::isfinite(x)) return std::nullopt;
        at_ = end;
        return x;
    }
    // An arc's flag: one digit, which may stand right before the next number.
    std::optional<double> flag() {
        skipSeparators();
        if (at_ < s_.size() && (s_[at_] == '0' || s_[at_] == '1')) return s_[at_++] - '0';
        return std::nullopt;
    }

private:
    std::string_view s_;
    std::size_t at_ = 0;
};

// How many numbers one step of each command takes.
int arity(char upper) {
    switch (upper) {
    case 'M': case 'L': case 'T': return 2;
    case 'H': case 'V': return 1;
    case 'S': case 'Q': return 4;
    case 'C': return 6;
    case 'A': return 7;
    default: return 0;
    }
}

}  // namespace

void addPathExtent(std::string_view d, SvgFrame& frame) {
    NumberReader in(d);
    vec2 current{0, 0}, subpathStart{0, 0};
    char cmd = 0;
    while (!in.atEnd()) {
        if (!in.atNumber()) {
            const auto c = in.command();
            cmd = c ? *c : 0;
        } else if (cmd == 0) {
            return;   // numbers before any command
        }
        const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(cmd)));
        const bool relative = cmd != upper;
        if (upper == 'Z') {
            current = subpathStart;
            cmd = 0;   // numbers may not follow a close
            continue;
        }
        const int n = arity(upper);
        if (n == 0) return;
        double v[7];
        for (int i = 0; i < n; ++i) {
            const auto x = upper == 'A' && (i == 3 || i == 4) ? in.flag() : in.number();
            if (!x) return;
            v[i] = *x;
        }
        const vec2 base = relative ? current : vec2{0, 0};
        auto point = [&](int i) { return base + vec2{v[i], v[i + 1]}; };
        vec2 end = current;
        switch (upper) {
        case 'H': end = {relative ? current.x + v[0] : v[0], current.y}; break;
        case 'V': end = {current.x, relative ? current.y + v[0] : v[0]}; break;
        case 'A': {
            end = point(5);
            // The arc lies on an ellipse through both ends: within reach R of
            // its centre, which is within R of each end.
            const double reach = std::max({std::abs(v[0]), std::abs(v[1]), length(end - current) / 2});
            frame.add({std::max(current.x, end.x) - reach, std::max(current.y, end.y) - reach}, 0);
            frame.add({std::min(current.x, end.x) + reach, std::min(current.y, end.y) + reach}, 0);
            break;
        }
        default:
            for (int i = 0; i + 2 < n; i += 2) frame.add(point(i), 0);   // control points
            end = point(n - 2);
        }
        frame.add(end, 0);   // each segment's start was the end before (or a move's point)
        current = end;
        if (upper == 'M') {
            subpathStart = current;
            cmd = relative ? 'l' : 'L';   // more pairs after a move are lines
        }
    }
}

void addPointsExtent(std::string_view points, SvgFrame& frame) {
    NumberReader in(points);
    for (;;) {
        const auto x = in.number();
        const auto y = x ? in.number() : std::nullopt;
        if (!y) return;
        frame.add({*x, *y}, 0);
    }
}

void addTextExtent(vec2 anchor, std::string_view text, double fontSize, std::string_view textAnchor, double degrees,
                   SvgFrame& frame) {
    const std::size_t chars = codePointCount(text);
    const double width = 0.6 * fontSize * static_cast<double>(chars);
    const double x0 = textAnchor == "start" ? 0 : textAnchor == "end" ? -width : -width / 2;
    const double a = degrees * 3.141592653589793 / 180.0, cs = std::cos(a), sn = std::sin(a);
    for (double x : {x0, x0 + width})
        for (double y : {-0.25 * fontSize, 0.9 * fontSize}) frame.add(anchor + vec2{x * cs - y * sn, x * sn + y * cs}, 0);
}

}  // namespace g2d::rt
