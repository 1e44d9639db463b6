#pragma once
// Renders ANTLR's syntax errors in words: "expected `;`, found `}`".
#include <antlr4-runtime.h>

#include "diag/diagnostic.hpp"

namespace g2d {

class SyntaxErrorListener : public antlr4::BaseErrorListener {
public:
    SyntaxErrorListener(FileId file, Diagnostics& diags) : file_(file), diags_(diags) {}

    void syntaxError(antlr4::Recognizer* recognizer, antlr4::Token* offending, size_t line,
                     size_t charPositionInLine, const std::string& msg,
                     std::exception_ptr e) override;

    std::size_t count() const { return count_; }

private:
    FileId file_;
    Diagnostics& diags_;
    std::size_t count_ = 0;
    std::size_t lastLine_ = 0;
};

// How a token looks in a message: `;`, a name `foo`, end of file, ...
std::string describeToken(const antlr4::Token* token);
// Human words for the set of tokens the parser expected.
std::string describeExpected(const antlr4::misc::IntervalSet& expected,
                             const antlr4::dfa::Vocabulary& vocabulary);

}  // namespace g2d
