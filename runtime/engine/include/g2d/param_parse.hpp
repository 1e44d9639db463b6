#pragma once
// Reads `-D NAME=VALUE` values as typed parameter values, the same way for
// the interpreter and for compiled grammars.
#include <optional>
#include <string>
#include <vector>

#include "g2d/value.hpp"

namespace g2d::rt {

enum class ParamType { Int, Float, Bool, String, Vec2, Enum, Vec3 };

// Accepted forms: int `-12`; float `2.5`, `1e-3`, `7`; bool `true`/`false`;
// string: anything; vec2 `x,y` or `(x, y)` as the language writes it (vec3
// likewise with three numbers); enum:
// one of `enumValues`, alone or after the enum's name (`Mode.Big`).
std::optional<Value> parseParamValue(ParamType type, const std::string& text, int enumId = -1,
                                     const std::vector<std::string>& enumValues = {}, const std::string& enumName = "");

}  // namespace g2d::rt
