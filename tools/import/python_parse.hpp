#pragma once
// The syntax tree of one Python 3 expression, as model_gen grammars write them,
// and its parser (hand-written tokenizer + precedence climbing). Everything is
// parsed that Python parses in such expressions; python_expr.cpp decides what
// has a g2d counterpart, so its messages can name the construct and its column.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace g2d::import::py {

struct Node;
using NodePtr = std::unique_ptr<Node>;

// One piece of an f-string: literal text, or a replacement field.
struct FPart {
    std::string literal;     // decoded text when expr < 0
    int expr = -1;           // index into Node::kids
    std::string spec;        // the format spec after ':' (without it)
    int specColumn = 0;
};

struct Node {
    enum class Kind {
        Int,      // text: decimal digits (underscores and 0x/0o/0b resolved)
        Float,    // text: the literal as written, without underscores
        Str,      // text: the decoded value
        FStr,     // parts; kids: the fields' expressions
        Bool,     // text: "True" or "False"
        None,
        Name,     // text
        Attr,     // kids[0].text
        Subscript,// kids[0][kids[1]]
        Call,     // kids[0](kids[1..]); keywords[i] names kids[i + 1] ("" if positional)
        Unary,    // text: "-", "+", "~"; kids[0]
        Not,      // kids[0]
        Binary,   // text: the operator (+ - * / // % ** @ | ^ & << >>); kids[0], kids[1]
        BoolOp,   // text: "and" / "or"; kids[0], kids[1]
        Compare,  // kids[0] ops[0] kids[1] ops[1] kids[2] …
        IfExp,    // kids[0] if kids[1] else kids[2]
        Tuple,
        List,
    };
    Kind kind;
    int column = 0;                 // the node's token (a binary node's: its operator)
    std::string text;
    std::vector<NodePtr> kids;
    std::vector<std::string> keywords;  // Call
    std::vector<std::string> ops;       // Compare ("==", "<", "in", "not in", "is", "is not" …)
    std::vector<int> opColumns;         // Compare
    std::vector<FPart> parts;           // FStr
    bool parenthesized = false;         // written `( … )`: the translation keeps the grouping
    int height = 1;                     // longest path to a leaf: bounds the translator's recursion
};

struct ParseResult {
    NodePtr root;            // null when the text does not parse (or hits a limit)
    std::string problem;
    int column = 0;
};

// Never throws. Nesting beyond kMaxDepth brackets/prefix operators, or a tree
// higher than kMaxHeight, is refused with a problem.
inline constexpr int kMaxDepth = 200;
inline constexpr int kMaxHeight = 500;
ParseResult parsePython(std::string_view source);

}  // namespace g2d::import::py
