#include "g2d/view_box.hpp"

#include <charconv>
#include <cmath>
#include <vector>

#include "g2d/ops.hpp"
#include "g2d/value.hpp"

namespace g2d::rt {

namespace {

std::string point(vec2 p) { return "(" + formatNumber(p.x) + ", " + formatNumber(p.y) + ")"; }

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    return b == std::string::npos ? "" : s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

}  // namespace

ViewBox checkedCanvas(vec2 lower, vec2 upper) {
    // Its size too is finite (the SVG states it): so are its corners.
    if (!std::isfinite(upper.x - lower.x) || !std::isfinite(upper.y - lower.y))
        throw OpError("the canvas must be finite, but its corners are " + point(lower) + " and " + point(upper));
    if (!(lower.x < upper.x && lower.y < upper.y))
        throw OpError("the canvas is empty: its first corner " + point(lower) +
                      " must lie below and left of its second " + point(upper));
    // + 0.0: a corner of -0 is written as 0.
    return ViewBox{lower.x + 0.0, lower.y + 0.0, upper.x + 0.0, upper.y + 0.0};
}

std::optional<ViewBox> parseViewBox(const std::string& text, std::string& error) {
    std::vector<double> xs;
    for (std::size_t start = 0;;) {
        const auto comma = text.find(',', start);
        const std::string part = trimmed(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        double x = 0;
        const auto r = std::from_chars(part.data(), part.data() + part.size(), x);
        if (part.empty() || r.ec != std::errc() || r.ptr != part.data() + part.size() || !std::isfinite(x)) {
            error = "expected four numbers X0,Y0,X1,Y1 (the lower left and the upper right corner, y up)";
            return std::nullopt;
        }
        xs.push_back(x);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (xs.size() != 4) {
        error = "expected four numbers X0,Y0,X1,Y1 (the lower left and the upper right corner, y up)";
        return std::nullopt;
    }
    if (!(xs[0] < xs[2] && xs[1] < xs[3])) {
        error = "the box is empty: X0 must be less than X1 and Y0 less than Y1";
        return std::nullopt;
    }
    if (!std::isfinite(xs[2] - xs[0]) || !std::isfinite(xs[3] - xs[1])) {
        error = "the box is too large";
        return std::nullopt;
    }
    return ViewBox{xs[0] + 0.0, xs[1] + 0.0, xs[2] + 0.0, xs[3] + 0.0};
}

}  // namespace g2d::rt
