#pragma once
// Reads an example drawn in any vector editor and saved as SVG. The subset
// (docs/infer-svg.md says the same for users):
//
// - Drawn: <line>, <polyline>, <polygon>, <rect> (no rx/ry rounding) and
//   <path> with straight commands only (M L H V Z, either case, implicit
//   repeats). Curves (C S Q T A) are an error naming the command.
// - <g> is read; <defs>, <symbol>, <clipPath>, <mask>, <pattern>, <marker>,
//   <metadata>, <title>, <desc>, gradients and <filter> are skipped, as are
//   elements of other XML namespaces (the editor's own, e.g. Inkscape's) and
//   anything with display="none" (hidden layers). <use>, <text>, <image>,
//   <circle>, <ellipse>, a nested <svg>, a non-empty <style> and any other
//   element are an error.
// - transform (translate, scale, rotate with optional centre, matrix, skewX,
//   skewY) on the element and all its ancestors, the root <svg> included. The
//   root's viewBox, x, y, width and height are ignored: coordinates are user
//   units of the root.
// - Edge label = stroke colour, area label = fill colour, from the attribute
//   or style="..." (which wins), inherited as in SVG: stroke none and fill
//   black unless given. Colours are #rgb, #rrggbb, rgb(r, g, b) (numbers or
//   percentages) or a CSS colour name, and come out as #rrggbb in lower case;
//   "transparent" is none; gradients (url(...)) and currentColor are errors.
//   Opacity and stroke width are ignored.
// - Every stroked element draws edges. A closed outline (polygon, rect, a
//   path subpath ended by Z, or a polyline or subpath ending where it starts)
//   whose fill is not none is an area: each edge's side takes the innermost
//   (smallest) filled shape around a point just beside the edge's middle; a
//   hole by the element's fill-rule does not count. Labels are numbered by
//   first appearance ("Line0", "Area0", ...); labels no edge uses are left
//   out. Brush lengths are not given and no brush is rigid.
// - Units: 40 user units are one example unit (Merrell's grid cell, as the
//   JSON reader has it); y is flipped to point up.
// - Points closer than 0.5 user units are one vertex (the first drawn keeps
//   its place); an edge is split where a vertex lies on it and where it
//   crosses another; duplicate edges are one (an error if their strokes
//   differ); edges shorter than 0.5 are dropped; a stroked point that
//   touches no edge is an error, and so is a drawing without edges.
// - The example's name: the root's <title>, else the file name's stem.
//   Vertices and edges are located as "line N" of their element.
#include <string>

#include "infer/example_shape.hpp"

namespace g2d::infer {

// `path` names the input in messages. Throws InputError ("PATH:LINE: ...").
ExampleShape readExampleSvg(const std::string& text, const std::string& path);

}  // namespace g2d::infer
