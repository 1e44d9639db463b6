#pragma once
// Semantic analysis: ASTs (the main file and its imports) in, typed IR out.
#include <optional>
#include <vector>

#include "ast/ast.hpp"
#include "diag/diagnostic.hpp"
#include "ir/ir.hpp"

namespace g2d {

// `programs` are in dependency order (imports before importers); the last
// one is the main file. Returns the IR when there are no errors.
std::optional<ir::Program> analyze(const std::vector<const ast::Program*>& programs, Diagnostics& diags);

}  // namespace g2d
