#include "parse/parser.hpp"

#include <antlr4-runtime.h>

#include "G2dParser.h"
#include "parse/ast_builder.hpp"
#include "parse/input_guard.hpp"
#include "parse/range_lexer.hpp"
#include "parse/syntax_errors.hpp"

namespace g2d {

std::optional<ast::Program> parseFile(const SourceManager& sm, FileId file, Diagnostics& diags,
                                      const ParseLimits& limits) {
    const SourceFile& src = sm.file(file);
    if (!checkEncoding(src, file, diags)) return std::nullopt;

    antlr4::ANTLRInputStream input(src.text);
    RangeLexer lexer(&input);
    lexer.removeErrorListeners();  // every lexical problem becomes a token the parser reports
    antlr4::CommonTokenStream tokens(&lexer);
    tokens.fill();
    if (!checkNesting(tokens.getTokens(), file, limits, diags)) return std::nullopt;

    G2dParser parser(&tokens);
    SyntaxErrorListener listener(file, diags);
    parser.removeErrorListeners();
    parser.addErrorListener(&listener);
    G2dParser::ProgramContext* tree = parser.program();
    if (listener.count() > 0) return std::nullopt;
    return buildAst(tree, file);
}

}  // namespace g2d
