#pragma once
// The language's binary operators on run-time values, for the interpreter
// and the constant folder (generated code calls the typed functions of
// ops.hpp that this dispatches to). Operands have the types the checker
// allows: int op int, float op float, vec ± vec, vec * float, vec / float,
// float * vec (vec2 or vec3), string + string, == and != on any two values of one type.
// Failures throw OpError with the words of ops.hpp.
#include "g2d/value.hpp"

namespace g2d::rt {

enum class BinaryOp { Add, Sub, Mul, Div, Mod, Lt, Le, Gt, Ge, Eq, Ne };

Value binaryOp(BinaryOp op, const Value& l, const Value& r);

}  // namespace g2d::rt
