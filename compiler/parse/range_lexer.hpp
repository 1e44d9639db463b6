#pragma once
// The lexer the parser reads: G2dLexer, except that `1.` just before a `.`
// is the int 1 of a range `1..10`. The grammar's lexer cannot look past its
// match without a semantic predicate, and ANTLR 4.9's C++ runtime leaks a
// configuration set each time a predicated lexer rule ends a token.
#include <memory>

#include "G2dLexer.h"

namespace g2d {

class RangeLexer : public G2dLexer {
public:
    using G2dLexer::G2dLexer;
    std::unique_ptr<antlr4::Token> nextToken() override;
};

}  // namespace g2d
