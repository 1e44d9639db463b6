#include "parse/input_guard.hpp"

#include "G2dLexer.h"
#include "g2d/utf8.hpp"

namespace g2d {

namespace {

Span tokenSpan(const antlr4::Token* t, FileId file) {
    auto line = static_cast<std::uint32_t>(t->getLine());
    auto col = static_cast<std::uint32_t>(t->getCharPositionInLine() + 1);
    return Span{file, line, col, line, col + 1};
}

}  // namespace

bool checkEncoding(const SourceFile& src, FileId file, Diagnostics& diags) {
    std::uint32_t line = 1, col = 1;
    for (std::size_t i = 0; i < src.text.size();) {
        unsigned char c = static_cast<unsigned char>(src.text[i]);
        if (c == 0) {
            diags.error(Span{file, line, col, line, col + 1},
                        "file contains a NUL byte: this looks like a binary file, not g2d source");
            return false;
        }
        std::size_t n = rt::utf8SequenceLength(src.text, i);
        if (n == 0) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "0x%02X", c);
            diags.error(Span{file, line, col, line, col + 1},
                        std::string("invalid UTF-8 (byte ") + hex + "): g2d source must be UTF-8 text");
            return false;
        }
        if (c == '\n') { ++line; col = 1; } else { ++col; }
        i += n;
    }
    return true;
}

bool checkNesting(const std::vector<antlr4::Token*>& tokens, FileId file, const ParseLimits& limits,
                  Diagnostics& diags) {
    std::size_t depth = 0, prefixRun = 0, conditionals = 0, operators = 0;
    bool previousIsOperand = false;
    for (const antlr4::Token* t : tokens) {
        const std::string text = t->getText();
        const auto type = t->getType();
        auto fail = [&](const std::string& what) {
            diags.error(tokenSpan(t, file), what);
            return false;
        };
        if (text == "(" || text == "{" || text == "-[" || text == "<-[") {
            if (++depth > limits.maxNesting)
                return fail("nesting is too deep (more than " + std::to_string(limits.maxNesting) + " levels)");
        } else if ((text == ")" || text == "}" || text == "]->" || text == "]-") && depth > 0) {
            --depth;
        }
        const bool isPrefix = !previousIsOperand && (text == "-" || text == "+" || text == "!" || text == "not");
        prefixRun = isPrefix ? prefixRun + 1 : 0;
        if (prefixRun > limits.maxNesting)
            return fail("too many prefix operators in a row (more than " + std::to_string(limits.maxNesting) + ")");
        if (text == "?" && ++conditionals > limits.maxNesting)
            return fail("conditional expressions are nested too deeply (more than " +
                        std::to_string(limits.maxNesting) + ")");
        if (type != G2dLexer::ID && type != G2dLexer::INT && type != G2dLexer::FLOAT &&
            type != G2dLexer::STRING && ++operators > limits.maxOperatorsPerStatement)
            return fail("statement is too long (more than " + std::to_string(limits.maxOperatorsPerStatement) +
                        " operators)");
        if (text == ";" || text == "{" || text == "}") { conditionals = 0; operators = 0; }
        previousIsOperand = type == G2dLexer::ID || type == G2dLexer::INT || type == G2dLexer::FLOAT ||
                            type == G2dLexer::STRING || text == ")" || text == "true" || text == "false";
    }
    return true;
}

}  // namespace g2d
