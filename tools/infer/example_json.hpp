#pragma once
// Reads an example in the format of Merrell's web app (PMUGG): its `data`
// array, versions 1-5, alone or as the `data` member of an object (the files
// in shared/reference/merrell/examples also hold `settings`, whose `Major
// Grid Spacing` and `Extents` give the units and the canvas).
#include <string>

#include "infer/example_shape.hpp"

namespace g2d::infer {

// `path` names the input in messages. Throws InputError.
ExampleShape readExampleJson(const std::string& text, const std::string& path);

}  // namespace g2d::infer
