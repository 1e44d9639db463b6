#pragma once
// What an SVG path, polyline or text covers, for the drawing's frame (the
// viewBox): without it a grammar's paths and labels are clipped.
#include <string_view>

#include "g2d/vec_math.hpp"

namespace g2d::rt {

struct SvgFrame;

// Every point of path data `d` (absolute and relative commands), control
// points included, and an arc's whole circle of reach: a cover, not always
// the tightest. Stops quietly at the first malformed part, as viewers do.
void addPathExtent(std::string_view d, SvgFrame& frame);
// The points of a polyline's `points`.
void addPointsExtent(std::string_view points, SvgFrame& frame);

// A text drawn at `anchor` (translate, rotate by `degrees`, upright) whose
// glyphs are estimated: 0.6 em wide on average, 0.9 em above the baseline
// and 0.25 em below it. `textAnchor` is "start", "middle" or "end".
void addTextExtent(vec2 anchor, std::string_view text, double fontSize, std::string_view textAnchor, double degrees,
                   SvgFrame& frame);

}  // namespace g2d::rt
