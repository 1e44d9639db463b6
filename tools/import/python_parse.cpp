#include "import/python_parse.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <utility>

#include "import/python_lexer.hpp"

namespace g2d::import::py {
namespace {

bool isKeyword(std::string_view w) {
    static constexpr std::string_view kWords[] = {
        "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class", "continue",
        "def", "del", "elif", "else", "except", "finally", "for", "from", "global", "if", "import", "in",
        "is", "lambda", "nonlocal", "not", "or", "pass", "raise", "return", "try", "while", "with", "yield"};
    for (std::string_view k : kWords)
        if (k == w) return true;
    return false;
}

NodePtr make(Node::Kind kind, int column, std::string text = {}) {
    auto n = std::make_unique<Node>();
    n->kind = kind;
    n->column = column;
    n->text = std::move(text);
    return n;
}

// Python's binary levels, loosest first (precedence climbing in Parser::binary).
enum Level { kOr = 1, kAnd, kNot, kCompare, kBitOr, kBitXor, kBitAnd, kShift, kAdd, kMul, kUnary, kPower };

// The recursive functions keep their frames small (sanitized debug builds give
// every temporary its own slot): messages are built in these out-of-line helpers.
[[noreturn]] [[gnu::noinline]] void failText(int column, const char* before, const std::string& text, const char* after) {
    fail(column, before + text + after);
}

class Parser {
public:
    Parser(std::vector<Token> tokens, int depth) : t_(std::move(tokens)), depth_(depth) {}

    NodePtr top() {
        if (peek().kind == Token::Kind::End) fail(peek().column, "empty expression");
        NodePtr n = test();
        if (peek().kind != Token::Kind::End) {
            if (isOp(",")) fail(peek().column, "a bare tuple `a, b` is not supported");
            unexpected();
        }
        return n;
    }

private:
    // Bounds the recursion: brackets, prefix operators, `**` and `if`-`else` all pass here.
    struct Guard {
        Guard(Parser& p, int column) : p_(p) {
            if (++p_.depth_ > kMaxDepth) tooDeep(column);
        }
        ~Guard() { --p_.depth_; }
        [[noreturn]] [[gnu::noinline]] static void tooDeep(int column) {
            fail(column, "expression nested too deeply (more than " + std::to_string(kMaxDepth) + " levels)");
        }
        Parser& p_;
    };

    const Token& peek(std::size_t ahead = 0) const { return t_[std::min(pos_ + ahead, t_.size() - 1)]; }
    const Token& take() { return pos_ + 1 < t_.size() ? t_[pos_++] : t_.back(); }
    bool isOp(std::string_view op, std::size_t ahead = 0) const {
        return peek(ahead).kind == Token::Kind::Op && peek(ahead).text == op;
    }
    bool isWord(std::string_view w, std::size_t ahead = 0) const {
        return peek(ahead).kind == Token::Kind::Name && peek(ahead).text == w;
    }
    static std::string describe(const Token& t) {
        switch (t.kind) {
            case Token::Kind::End: return "end of expression";
            case Token::Kind::Str: case Token::Kind::FStr: return "string";
            default: return "`" + t.text + "`";
        }
    }
    [[noreturn]] [[gnu::noinline]] void unexpected() const {
        const Token& t = peek();
        if (t.kind == Token::Kind::Op && t.text == "!") fail(t.column, "`!` is not Python; write `not`");
        if (t.kind == Token::Kind::Op && (t.text == "&" || t.text == "|") && pos_ > 0 && t_[pos_ - 1].text == t.text)
            fail(t_[pos_ - 1].column, t.text == "&" ? "`&&` is not Python; write `and`" : "`||` is not Python; write `or`");
        fail(t.column, "unexpected " + describe(t));
    }
    [[noreturn]] [[gnu::noinline]] void expected(const char* what) const {
        fail(peek().column, std::string("expected ") + what + ", found " + describe(peek()));
    }
    void expectOp(std::string_view op) {
        if (!isOp(op)) expected(op == ")" ? "`)`" : "`]`");
        take();
    }

    static NodePtr finish(NodePtr n) {
        int h = 0;
        for (const NodePtr& k : n->kids) h = std::max(h, k->height);
        n->height = h + 1;
        if (n->height > kMaxHeight) tooHigh(n->column);
        return n;
    }
    [[noreturn]] [[gnu::noinline]] static void tooHigh(int column) {
        fail(column, "expression too long (more than " + std::to_string(kMaxHeight) + " levels)");
    }
    static NodePtr pair(Node::Kind kind, const Token& op, NodePtr l, NodePtr r) {
        NodePtr n = make(kind, op.column, op.text);
        n->kids.push_back(std::move(l));
        n->kids.push_back(std::move(r));
        return finish(std::move(n));
    }

    NodePtr test() {
        Guard g(*this, peek().column);
        if (isWord("lambda")) fail(peek().column, "`lambda` expressions are not supported");
        NodePtr body = binary(kOr);
        if (isWord("if")) {
            NodePtr n = make(Node::Kind::IfExp, take().column);
            NodePtr cond = binary(kOr);
            if (!isWord("else")) expected("`else` of a conditional expression");
            take();
            n->kids.push_back(std::move(body));
            n->kids.push_back(std::move(cond));
            n->kids.push_back(test());
            return finish(std::move(n));
        }
        if (isOp(":=")) fail(peek().column, "assignment expressions (`:=`) are not supported");
        return body;
    }

    // The level of the binary operator at the cursor, 0 if none.
    int infixLevel() const {
        const Token& t = peek();
        if (t.kind == Token::Kind::Name) {
            if (t.text == "or") return kOr;
            if (t.text == "and") return kAnd;
            if (t.text == "in" || t.text == "is" || (t.text == "not" && isWord("in", 1))) return kCompare;
            return 0;
        }
        if (t.kind != Token::Kind::Op) return 0;
        static constexpr std::pair<std::string_view, int> kOps[] = {
            {"<", kCompare}, {">", kCompare}, {"==", kCompare}, {">=", kCompare}, {"<=", kCompare}, {"!=", kCompare},
            {"|", kBitOr}, {"^", kBitXor}, {"&", kBitAnd}, {"<<", kShift}, {">>", kShift}, {"+", kAdd}, {"-", kAdd},
            {"*", kMul}, {"/", kMul}, {"//", kMul}, {"%", kMul}, {"@", kMul}, {"**", kPower}};
        for (const auto& [op, level] : kOps)
            if (t.text == op) return level;
        return 0;
    }

    // Binary operators of level minLevel and looser-binding operands; left-associative
    // except `**`, whose right operand may carry a sign (2 ** -1), as in Python.
    NodePtr binary(int minLevel) {
        NodePtr left = prefix(minLevel);
        for (;;) {
            const int level = infixLevel();
            if (level == 0 || level < minLevel) return left;
            if (level == kCompare) {
                left = comparison(std::move(left));
                continue;
            }
            const Token& op = take();
            if (level == kPower) {
                Guard g(*this, op.column);
                left = pair(Node::Kind::Binary, op, std::move(left), binary(kUnary));
            } else {
                left = pair(level <= kAnd ? Node::Kind::BoolOp : Node::Kind::Binary, op, std::move(left), binary(level + 1));
            }
        }
    }

    // `not` binds looser than comparisons, `-` tighter than `*` but looser than `**`.
    NodePtr prefix(int minLevel) {
        const Token& t = peek();
        const bool isNot = minLevel <= kNot && isWord("not");
        if (isNot || (minLevel <= kUnary && t.kind == Token::Kind::Op && (t.text == "-" || t.text == "+" || t.text == "~"))) {
            Guard g(*this, t.column);
            NodePtr n = isNot ? make(Node::Kind::Not, t.column) : make(Node::Kind::Unary, t.column, t.text);
            take();
            n->kids.push_back(binary(isNot ? kNot : kUnary));
            return finish(std::move(n));
        }
        if (isOp("!")) fail(t.column, "`!` is not Python; write `not`");
        return postfix();
    }

    std::string compareOp() const {
        if (infixLevel() != kCompare) return {};
        if (isWord("not")) return "not in";
        if (isWord("is")) return isWord("not", 1) ? "is not" : "is";
        return peek().text;
    }
    NodePtr comparison(NodePtr first) {
        NodePtr n = make(Node::Kind::Compare, peek().column);
        n->kids.push_back(std::move(first));
        for (std::string op = compareOp(); !op.empty(); op = compareOp()) {
            n->opColumns.push_back(take().column);
            if (op == "not in" || op == "is not") take();
            n->ops.push_back(std::move(op));
            n->kids.push_back(binary(kCompare + 1));
        }
        return finish(std::move(n));
    }

    NodePtr postfix() {
        NodePtr n = atom();
        for (;;) {
            if (isOp(".")) {
                const int column = take().column;
                if (peek().kind != Token::Kind::Name) expected("a name after `.`");
                NodePtr a = make(Node::Kind::Attr, column, take().text);
                a->kids.push_back(std::move(n));
                n = finish(std::move(a));
            } else if (isOp("(")) {
                n = call(std::move(n));
            } else if (isOp("[")) {
                NodePtr s = make(Node::Kind::Subscript, take().column);
                if (isOp(":")) fail(peek().column, "slices are not supported");
                s->kids.push_back(std::move(n));
                s->kids.push_back(test());
                if (isOp(":")) fail(peek().column, "slices are not supported");
                expectOp("]");
                n = finish(std::move(s));
            } else {
                return n;
            }
        }
    }

    NodePtr call(NodePtr callee) {
        NodePtr n = make(Node::Kind::Call, take().column);
        n->kids.push_back(std::move(callee));
        while (!isOp(")")) {
            if (isOp("*") || isOp("**")) failText(peek().column, "argument unpacking (`", peek().text, "`) is not supported");
            std::string keyword;
            if (peek().kind == Token::Kind::Name && isOp("=", 1)) {
                keyword = take().text;
                take();
            } else if (!n->keywords.empty() && !n->keywords.back().empty()) {
                fail(peek().column, "a positional argument follows a keyword argument");
            }
            n->kids.push_back(test());
            n->keywords.push_back(std::move(keyword));
            if (isWord("for")) fail(peek().column, "generator expressions are not supported");
            if (!isOp(",")) break;
            take();
        }
        expectOp(")");
        return finish(std::move(n));
    }

    // The elements of `( … )` or `[ … ]` after the opening bracket; true if a comma was seen.
    bool sequence(Node& n, std::string_view close, const char* comprehension) {
        bool comma = false;
        while (!isOp(close)) {
            if (isOp("*")) fail(peek().column, "unpacking (`*`) is not supported");
            n.kids.push_back(test());
            if (isWord("for")) fail(peek().column, comprehension);
            if (!isOp(",")) break;
            comma = true;
            take();
        }
        expectOp(close);
        return comma;
    }

    NodePtr atom() {
        const Token& t = peek();
        switch (t.kind) {
            case Token::Kind::Int: return make(Node::Kind::Int, t.column, take().text);
            case Token::Kind::Float: return make(Node::Kind::Float, t.column, take().text);
            case Token::Kind::Str: case Token::Kind::FStr: return strings();
            case Token::Kind::End: fail(t.column, "unexpected end of expression");
            case Token::Kind::Name:
                if (t.text == "True" || t.text == "False") return make(Node::Kind::Bool, t.column, take().text);
                if (t.text == "None") return make(Node::Kind::None, take().column);
                if (t.text == "await" || t.text == "yield") failText(t.column, "`", t.text, "` is not supported");
                if (isKeyword(t.text)) unexpected();
                return make(Node::Kind::Name, t.column, take().text);
            case Token::Kind::Op: break;
        }
        const int column = t.column;
        if (isOp("(")) {
            take();
            NodePtr n = make(Node::Kind::Tuple, column);
            const bool comma = sequence(*n, ")", "generator expressions are not supported");
            if (n->kids.size() == 1 && !comma) {
                n->kids[0]->parenthesized = true;
                return std::move(n->kids[0]);
            }
            return finish(std::move(n));
        }
        if (isOp("[")) {
            take();
            NodePtr n = make(Node::Kind::List, column);
            sequence(*n, "]", "list comprehensions are not supported");
            return finish(std::move(n));
        }
        if (isOp("{")) fail(column, "dict and set literals are not supported");
        if (isOp("...")) fail(column, "`...` is not supported");
        unexpected();
    }

    // Adjacent literals concatenate, as in Python; with an f-string only alone.
    NodePtr strings() {
        const Token first = take();
        if (first.kind == Token::Kind::FStr) {
            if (peek().kind == Token::Kind::Str || peek().kind == Token::Kind::FStr)
                fail(peek().column, "implicit concatenation with an f-string is not supported; write one f-string");
            return fstring(first);
        }
        NodePtr n = make(Node::Kind::Str, first.column, first.text);
        while (peek().kind == Token::Kind::Str) n->text += take().text;
        if (peek().kind == Token::Kind::FStr)
            fail(peek().column, "implicit concatenation with an f-string is not supported; write one f-string");
        return n;
    }

    NodePtr fstring(const Token& t) {
        NodePtr n = make(Node::Kind::FStr, t.column);
        const std::string& body = t.text;
        auto colAt = [&](std::size_t i) { return t.bodyColumn + codePoints(std::string_view(body).substr(0, i)); };
        std::string literal;
        std::size_t literalStart = 0;
        auto flush = [&] {
            if (literal.empty()) return;
            FPart p;
            p.literal = t.raw ? literal : decodeEscapes(literal, colAt(literalStart));
            n->parts.push_back(std::move(p));
            literal.clear();
        };
        std::size_t i = 0;
        while (i < body.size()) {
            const char c = body[i];
            if (literal.empty()) literalStart = i;
            if ((c == '{' || c == '}') && i + 1 < body.size() && body[i + 1] == c) {
                literal += c;
                i += 2;
                continue;
            }
            if (c == '}') fail(colAt(i), "single `}` in an f-string; write `}}`");
            if (c != '{') {
                literal += c;
                if (c == '\\' && i + 1 < body.size()) literal += body[++i];
                ++i;
                continue;
            }
            flush();
            const std::size_t start = i + 1;
            std::size_t j = start;
            int nesting = 0;
            char quote = 0;
            for (; j < body.size(); ++j) {
                const char d = body[j];
                if (quote) {
                    if (d == quote) quote = 0;
                } else if (d == '\'' || d == '"') {
                    quote = d;
                } else if (d == '(' || d == '[' || d == '{') {
                    ++nesting;
                } else if (nesting > 0 && (d == ')' || d == ']' || d == '}')) {
                    --nesting;
                } else if (nesting == 0 && (d == '}' || d == ':' || (d == '!' && (j + 1 >= body.size() || body[j + 1] != '=')))) {
                    break;
                }
            }
            if (j >= body.size()) fail(colAt(i), "unterminated `{` in an f-string");
            std::string_view expr = std::string_view(body).substr(start, j - start);
            const std::size_t last = expr.find_last_not_of(" \t");
            if (last == std::string_view::npos) fail(colAt(i), "empty expression in an f-string");
            if (expr[last] == '=' && (last == 0 || std::string_view("=!<>").find(expr[last - 1]) == std::string_view::npos))
                fail(colAt(start + last), "self-documenting `=` in an f-string is not supported");
            if (body[j] == '!') fail(colAt(j), "conversions (`!r`, `!s`) in f-strings are not supported");
            FPart p;
            if (body[j] == ':') {
                const std::size_t specStart = j + 1;
                while (j < body.size() && body[j] != '}') {
                    if (body[j] == '{') fail(colAt(j), "nested fields in an f-string format spec are not supported");
                    ++j;
                }
                if (j >= body.size()) fail(colAt(i), "unterminated `{` in an f-string");
                p.spec = body.substr(specStart, j - specStart);
                p.specColumn = colAt(specStart);
            }
            Parser sub(tokenize(expr, colAt(start)), depth_);
            p.expr = static_cast<int>(n->kids.size());
            n->kids.push_back(sub.top());
            n->parts.push_back(std::move(p));
            i = j + 1;
        }
        flush();
        return finish(std::move(n));
    }

    std::vector<Token> t_;
    std::size_t pos_ = 0;
    int depth_;
};

}  // namespace

ParseResult parsePython(std::string_view source) {
    ParseResult result;
    try {
        Parser parser(tokenize(source, 0), 0);
        result.root = parser.top();
    } catch (const Fail& f) {
        result.root.reset();
        result.problem = f.problem;
        result.column = f.column;
    } catch (const std::exception&) {
        result.root.reset();
        result.problem = "the expression could not be parsed (out of memory)";
        result.column = 0;
    }
    return result;
}

}  // namespace g2d::import::py
