#pragma once
// The SVG reader's attribute syntaxes: numbers, point lists, transform lists,
// straight path data and colours. Pure text in, values out; the element
// reader (example_svg.cpp) adds where in the file a SyntaxError was.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace g2d::infer::svg {

struct SyntaxError {
    std::string message;
};

struct UserPoint {
    double x = 0, y = 0;  // SVG user units, y down
};

// x' = a x + c y + e, y' = b x + d y + f (SVG's matrix(a b c d e f)).
struct Matrix {
    double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
    UserPoint apply(UserPoint p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
};
// `outer` after `inner`: the matrix of a child's transform inside its parent's.
Matrix operator*(const Matrix& outer, const Matrix& inner);

// A whole attribute that is one number, optionally followed by "px"; nullopt otherwise.
std::optional<double> parseLength(std::string_view text);
// Numbers separated by commas and/or white space (`points`).
std::vector<double> parseNumberList(std::string_view text);
// translate, scale, rotate, skewX, skewY and matrix, composed left to right.
Matrix parseTransform(std::string_view text);

struct Subpath {
    std::vector<UserPoint> points;
    bool closed = false;  // ended by Z/z
};
// Straight commands only (M L H V Z, either case); a lone moveto draws nothing
// and is left out, as SVG renders nothing for it.
std::vector<Subpath> parsePathData(std::string_view text);

// "#rrggbb" (lower case) for an opaque CSS colour (rt::cssColor: #hex,
// rgb(), hsl(), the named colours, any case); nullopt for anything else.
std::optional<std::string> parseColor(std::string_view text);

std::string_view trim(std::string_view text);

}  // namespace g2d::infer::svg
