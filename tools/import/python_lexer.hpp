#pragma once
// Python's tokens, for python_parse.cpp: names, numbers (underscores and
// 0x/0o/0b resolved), strings with their escapes decoded, f-strings' raw
// bodies, and operators. Columns count code points from a base column.
#include <string>
#include <string_view>
#include <vector>

namespace g2d::import::py {

// A syntax problem at a column; internal only: parsePython catches it (the
// API never throws).
struct Fail {
    std::string problem;
    int column;
};
[[noreturn]] void fail(int column, std::string problem);
[[noreturn]] [[gnu::noinline]] void fail(int column, const char* problem);

struct Token {
    enum class Kind { Int, Float, Str, FStr, Name, Op, End };
    Kind kind = Kind::End;
    std::string text;   // Str: decoded value; FStr: the raw body; others: as written
    int column = 0;
    int bodyColumn = 0; // FStr: column of the body's first character
    bool raw = false;   // FStr: r-prefix (no escapes in literal parts)
};

// The tokens of `source`, the last one End; its first character is at
// column `baseColumn`. Throws Fail.
std::vector<Token> tokenize(std::string_view source, int baseColumn);

// Python's string escapes in `body` (a literal starting at `column`). Throws Fail.
std::string decodeEscapes(std::string_view body, int column);

// Columns count code points, so a caret under the source lines up with UTF-8 text.
int codePoints(std::string_view text);

}  // namespace g2d::import::py
