#pragma once
// Reads `-D NAME=VALUE` values as typed parameter values, the same way for
// the interpreter and for compiled grammars.
#include <optional>
#include <string>
#include <vector>

#include "g2d/value.hpp"

namespace g2d::rt {

enum class ParamType { Int, Float, Bool, String, Vec2, Enum };

// Accepted forms: int `-12`; float `2.5`, `1e-3`, `7`; bool `true`/`false`;
// string: anything; vec2 `x,y`; enum: one of `enumValues`.
std::optional<Value> parseParamValue(ParamType type, const std::string& text, int enumId = -1,
                                     const std::vector<std::string>& enumValues = {});

}  // namespace g2d::rt
