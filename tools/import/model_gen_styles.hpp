#pragma once
// How the original tool drew: its .svg_* attributes as g2d style properties,
// its units (1 graph unit = 1 cm = 35.43307 px) and its default drawings.

#include <optional>
#include <string>
#include <string_view>

namespace g2d::import {

inline constexpr double kPixelsPerUnit = 35.43307;   // svgwrite's 1 cm

// The g2d style property of a .svg_/.svgx_ key (".svg_stroke_width" →
// "stroke_width", ".svgx_rotate" → "rotate"), or nullopt for another key.
std::optional<std::string> stylePropertyOf(std::string_view key);

// Whether the tool passed the property to svgwrite in pixels (a plain number
// there is SVG user units), so that g2d needs it divided into graph units.
bool isPixelLength(std::string_view property);

// A length as the tool wrote it ("0.1mm", "3cm", "2px", "0.5") in graph units,
// or nullopt when the text is not a length.
std::optional<double> lengthInUnits(std::string_view text);

// A number as g2d source: shortest text that reads back the same.
std::string numberText(double value);

// The body of a g2d string literal (language.md §2): `"` and `\` escaped,
// line ends, tabs and NUL spelled out; with `braces`, a format template's
// `{` and `}` doubled.
std::string escapeString(std::string_view text, bool braces);
// A string as a g2d literal.
std::string quoted(std::string_view text);

// The tool's .svg_tag value (None, 'None', 'none', 'rect', …) as g2d's tag.
std::string tagOf(std::string_view toolTag);

}  // namespace g2d::import
