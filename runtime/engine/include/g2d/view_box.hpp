#pragma once
// A fixed frame for the SVG: the grammar's `canvas (x0, y0) to (x1, y1);` or
// the command line's `--viewbox X0,Y0,X1,Y1`. It replaces the frame fitted to
// the drawing exactly, with no margin: what lies outside is clipped, and
// every run of a grammar gets a picture of one size (animation frames).
// Precedence: --viewbox, then the canvas, then the fitted frame.
#include <optional>
#include <string>

#include "g2d/vec_math.hpp"

namespace g2d::rt {

// In graph units, y up as in the grammar: (x0, y0) the lower left corner,
// (x1, y1) the upper right; x0 < x1 and y0 < y1, all finite.
struct ViewBox {
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
};

// The canvas from its corners as a back end evaluates them (parameters may
// set them); throws OpError unless they are finite and `lower` lies below
// and left of `upper`. The compiler reports constant corners with the same words.
ViewBox checkedCanvas(vec2 lower, vec2 upper);

// Reads --viewbox's `X0,Y0,X1,Y1` (spaces allowed around the numbers). On
// failure returns nothing and sets `error` (without the option's name).
std::optional<ViewBox> parseViewBox(const std::string& text, std::string& error);

}  // namespace g2d::rt
