#pragma once
// The colours an inferred grammar draws its labels in: the written grammar's
// styles and the studio's pictures of the example, its primitives and rules
// use these, so a label looks the same everywhere.
#include <string>

#include "infer/labelled_example.hpp"

namespace g2d::infer {

// An area label's fill: its own colour, else a light one of a fixed palette by index.
std::string areaColour(const LabelledExample& ex, int area);
// An edge label's stroke: its brush's colour, else near-black.
std::string edgeColour(const LabelledExample& ex, int label);

}  // namespace g2d::infer
