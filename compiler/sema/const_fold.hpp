#pragma once
// Compile-time evaluation of constant IR expressions, and facts about what an
// expression depends on.
#include <optional>

#include "ir/ir.hpp"

namespace g2d::sema {

// The value of `e` if it can be known at compile time: literals, folded
// constants and pure built-ins only (no parameters, elements or randomness).
// When evaluation certainly fails (division by zero, integer overflow), sets
// `*error` (if given) to the reason and returns nothing.
std::optional<ir::Value> fold(const ir::Expr& e, const ir::Program& prog, std::string* error = nullptr);

bool usesRandom(const ir::Expr& e, const ir::Program& prog);
bool usesParams(const ir::Expr& e, const ir::Program& prog);
bool readsElements(const ir::Expr& e);
bool readsLocals(const ir::Expr& e);

double asNumber(const ir::Value& v);   // int or float value as double

}  // namespace g2d::sema
