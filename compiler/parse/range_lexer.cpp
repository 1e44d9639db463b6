#include "parse/range_lexer.hpp"

#include <antlr4-runtime.h>

namespace g2d {

std::unique_ptr<antlr4::Token> RangeLexer::nextToken() {
    std::unique_ptr<antlr4::Token> token = G2dLexer::nextToken();
    auto* digitsDot = dynamic_cast<antlr4::CommonToken*>(token.get());
    if (!digitsDot || digitsDot->getType() != FLOAT || _input->LA(1) != '.') return token;
    const std::string text = digitsDot->getText();
    if (text.size() < 2 || text.back() != '.' || text[0] == '.') return token;
    // Give the `.` back: it starts the range's `..`.
    digitsDot->setType(INT);
    digitsDot->setText(text.substr(0, text.size() - 1));
    digitsDot->setStopIndex(digitsDot->getStopIndex() - 1);
    _input->seek(_input->index() - 1);
    setCharPositionInLine(getCharPositionInLine() - 1);
    return token;
}

}  // namespace g2d
