#pragma once
// Pictures of an inference for a person (the studio's infer mode): the
// example with each vertex marked by its primitive, a primitive's star, and
// one side of a rule as a small graph. Plain SVG text (y down, no script, no
// external reference), coloured as the written grammar colours its labels
// (label_colours.hpp).
#include <string>

#include "infer/labelled_example.hpp"
#include "infer/rule_sides.hpp"

namespace g2d::infer {

// Primitive k's marker colour: distinct for neighbouring indices, the same every time.
std::string primitiveColour(int primitive);

// The example: its edges in their labels' colours, the area on each side as
// a band along the edge, each vertex a dot of its primitive's colour named
// "P<k>" (its <title>).
std::string exampleSvg(const LabelledExample& ex);

// Primitive k's star: its half-edges from the centre (dashed: pointing in,
// against the label's direction) and the areas between them as wedges.
std::string primitiveSvg(const LabelledExample& ex, int primitive);

// A rule side: its vertices placed along the edges' directions at the
// example's mean length per label, the interface nodes as hollow dots.
// Empty for a side with nothing (a starter's right side).
std::string ruleSideSvg(const LabelledExample& ex, const RuleSide& side);

}  // namespace g2d::infer
