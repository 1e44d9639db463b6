#pragma once
// The language's built-in functions: names, signatures, result types.
#include <optional>
#include <string>
#include <vector>

#include "ir/ir.hpp"

namespace g2d::sema {

struct BuiltinInfo {
    std::string name;
    int minArgs = 0, maxArgs = 0;    // maxArgs -1: variadic
    ir::Builtin builtin;             // one of its built-ins (those of one name all draw, or none does)
    std::string signature;           // for messages, e.g. "rotate(v: vec2, angle: float[, centre: vec2])"
};

// All built-in function names with their signatures, for lookup and docs.
const std::vector<BuiltinInfo>& builtinFunctions();
const BuiltinInfo* findBuiltin(const std::string& name);
// Whether calling it draws from the run's generator (rt::BuiltinEntry::drawsRandom).
bool drawsRandom(const BuiltinInfo& b);

// Picks the overload for `name` given argument types. On success returns the
// builtin, the parameter types the arguments are converted to, and the
// result type; on failure returns an explanation.
struct BuiltinResolution {
    ir::Builtin builtin;
    std::vector<ir::Type> paramTypes;
    ir::Type result;
};
struct BuiltinError {
    std::string message;
    int argument = -1;               // which argument is at fault (-1: the call)
};
std::variant<BuiltinResolution, BuiltinError> resolveBuiltin(const std::string& name,
                                                             const std::vector<ir::Type>& args,
                                                             const ir::Program& prog);

}  // namespace g2d::sema
