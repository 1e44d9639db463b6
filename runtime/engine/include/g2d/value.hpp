#pragma once
// Attribute values at run time, and how they print. Printing is specified
// (shortest round-trip decimal for floats) so that the interpreter and the
// generated code write byte-identical SVG and JSON.
#include <string>
#include <variant>

#include "g2d/vec_math.hpp"

namespace g2d::rt {

struct EnumVal {
    int enumId = -1;
    int index = -1;
    bool operator==(const EnumVal&) const = default;
};

// vec3 comes last so that the older alternatives keep their indices.
using Value = std::variant<long long, double, bool, std::string, vec2, EnumVal, vec3>;

// Shortest decimal that reads back as the same double ("0.1", "3", "1e+300");
// -0 prints as "0".
std::string formatNumber(double x);
// Fixed notation with `decimals` digits ("{:.3}" in format templates).
std::string formatFixed(double x, int decimals);
// How str() and `{}` print a value (vectors as "(x, y)" or "(x, y, z)"; enums need names, so
// they are printed by the caller).
std::string toString(const Value& v);

}  // namespace g2d::rt
