#pragma once
// Converts a syntactically valid ANTLR parse tree into our AST.
#include "G2dParser.h"
#include "ast/ast.hpp"

namespace g2d {

ast::Program buildAst(G2dParser::ProgramContext* tree, FileId file);

}  // namespace g2d
