#pragma once
// Turns one source file into an AST. The ANTLR parse tree stays in here.
#include <optional>

#include "ast/ast.hpp"
#include "diag/diagnostic.hpp"

namespace g2d {

struct ParseLimits {
    std::size_t maxNesting = 200;        // brackets and braces, prefix-operator runs, `?:` chains
    std::size_t maxOperatorsPerStatement = 4000;
};

// Parses the file `file` of `sm`. Returns no program when the file has syntax
// errors (they are reported in `diags`).
std::optional<ast::Program> parseFile(const SourceManager& sm, FileId file, Diagnostics& diags,
                                      const ParseLimits& limits = {});

}  // namespace g2d
