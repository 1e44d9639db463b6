#include "import/python_parse.hpp"
#include "g2d/utf8.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <utility>

namespace g2d::import::py {
namespace {

// Internal only: parsePython catches it (the API never throws).
struct Fail {
    std::string problem;
    int column;
};
[[noreturn]] void fail(int column, std::string problem) { throw Fail{std::move(problem), column}; }
[[noreturn]] [[gnu::noinline]] void fail(int column, const char* problem) { throw Fail{problem, column}; }

struct Token {
    enum class Kind { Int, Float, Str, FStr, Name, Op, End };
    Kind kind = Kind::End;
    std::string text;   // Str: decoded value; FStr: the raw body; others: as written
    int column = 0;
    int bodyColumn = 0; // FStr: column of the body's first character
    bool raw = false;   // FStr: r-prefix (no escapes in literal parts)
};

bool isIdentStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isIdentChar(char c) { return isIdentStart(c) || isDigit(c); }

// Columns count code points, so a caret under the source lines up with UTF-8 text.
int codePoints(std::string_view text) { return static_cast<int>(rt::codePointCount(text)); }

void appendUtf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

int hexValue(char c) {
    if (isDigit(c)) return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// Python's string escapes; an unknown escape keeps its backslash, as Python does.
std::string decodeEscapes(std::string_view body, int column) {
    std::string out;
    for (std::size_t i = 0; i < body.size(); ++i) {
        if (body[i] != '\\' || i + 1 >= body.size()) {
            out += body[i];
            continue;
        }
        const char e = body[++i];
        switch (e) {
            case '\n': break;
            case '\\': out += '\\'; break;
            case '\'': out += '\''; break;
            case '"': out += '"'; break;
            case 'n': out += '\n'; break;
            case 't': out += '\t'; break;
            case 'r': out += '\r'; break;
            case 'a': out += '\a'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'v': out += '\v'; break;
            case 'x': case 'u': case 'U': {
                const std::size_t digits = e == 'x' ? 2 : e == 'u' ? 4 : 8;
                std::uint32_t cp = 0;
                for (std::size_t k = 0; k < digits; ++k) {
                    const int h = i + 1 + k < body.size() ? hexValue(body[i + 1 + k]) : -1;
                    if (h < 0) fail(column, std::string("truncated \\") + e + " escape in a string");
                    cp = cp * 16 + static_cast<std::uint32_t>(h);
                }
                if (cp > 0x10FFFF) fail(column, "invalid \\U escape in a string");
                i += digits;
                appendUtf8(out, cp);
                break;
            }
            case 'N': fail(column, "\\N{…} escapes are not supported; write the character itself");
            default:
                if (e >= '0' && e <= '7') {
                    std::uint32_t cp = 0;
                    std::size_t k = i;
                    for (; k < body.size() && k < i + 3 && body[k] >= '0' && body[k] <= '7'; ++k)
                        cp = cp * 8 + static_cast<std::uint32_t>(body[k] - '0');
                    i = k - 1;
                    appendUtf8(out, cp);
                } else {
                    out += '\\';
                    out += e;
                }
        }
    }
    return out;
}

class Lexer {
public:
    Lexer(std::string_view src, int base) : src_(src), base_(base) {}

    std::vector<Token> run() {
        std::vector<Token> tokens;
        for (;;) {
            skipSpace();
            Token t;
            t.column = col(pos_);
            if (pos_ >= src_.size()) {
                tokens.push_back(std::move(t));
                return tokens;
            }
            const char c = src_[pos_];
            if (isDigit(c) || (c == '.' && pos_ + 1 < src_.size() && isDigit(src_[pos_ + 1]))) {
                number(t);
            } else if (isIdentStart(c)) {
                const std::size_t start = pos_;
                while (pos_ < src_.size() && isIdentChar(src_[pos_])) ++pos_;
                t.text = std::string(src_.substr(start, pos_ - start));
                if (pos_ < src_.size() && (src_[pos_] == '\'' || src_[pos_] == '"') && isPrefix(t.text))
                    string(t, start);
                else
                    t.kind = Token::Kind::Name;
            } else if (c == '\'' || c == '"') {
                string(t, pos_);
            } else {
                op(t);
            }
            tokens.push_back(std::move(t));
        }
    }

private:
    int col(std::size_t offset) const { return base_ + codePoints(src_.substr(0, offset)); }

    void skipSpace() {
        while (pos_ < src_.size()) {
            const char c = src_[pos_];
            if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f') {
                ++pos_;
            } else if (c == '\\' && pos_ + 1 < src_.size() && (src_[pos_ + 1] == '\n' || src_[pos_ + 1] == '\r')) {
                pos_ += 2;
            } else if (c == '#') {
                while (pos_ < src_.size() && src_[pos_] != '\n') ++pos_;
            } else {
                return;
            }
        }
    }

    static bool isPrefix(const std::string& p) {
        std::string l;
        for (char ch : p) l += static_cast<char>(ch >= 'A' && ch <= 'Z' ? ch - 'A' + 'a' : ch);
        return l == "r" || l == "u" || l == "f" || l == "b" || l == "rb" || l == "br" || l == "fr" || l == "rf";
    }

    void digits(std::string& out, bool (*ok)(char)) {
        while (pos_ < src_.size() && (ok(src_[pos_]) || (src_[pos_] == '_' && pos_ + 1 < src_.size() && ok(src_[pos_ + 1])))) {
            if (src_[pos_] != '_') out += src_[pos_];
            ++pos_;
        }
    }

    void number(Token& t) {
        const int column = t.column;
        const char c = src_[pos_];
        if (c == '0' && pos_ + 1 < src_.size() && std::string_view("xXoObB").find(src_[pos_ + 1]) != std::string_view::npos) {
            const char b = static_cast<char>(src_[pos_ + 1] | 0x20);
            const int radix = b == 'x' ? 16 : b == 'o' ? 8 : 2;
            pos_ += 2;
            std::uint64_t value = 0;
            bool any = false;
            while (pos_ < src_.size() && (hexValue(src_[pos_]) >= 0 || src_[pos_] == '_')) {
                if (src_[pos_] != '_') {
                    const int d = hexValue(src_[pos_]);
                    if (d >= radix) fail(col(pos_), "invalid digit in a base-" + std::to_string(radix) + " literal");
                    if (value > (static_cast<std::uint64_t>(INT64_MAX) - static_cast<std::uint64_t>(d)) / static_cast<std::uint64_t>(radix))
                        fail(column, "integer literal too large for g2d's 64-bit int");
                    value = value * static_cast<std::uint64_t>(radix) + static_cast<std::uint64_t>(d);
                    any = true;
                }
                ++pos_;
            }
            if (!any) fail(column, "invalid integer literal");
            t.kind = Token::Kind::Int;
            t.text = std::to_string(value);
            return;
        }
        std::string text;
        digits(text, isDigit);
        bool isFloat = false;
        if (pos_ < src_.size() && src_[pos_] == '.') {
            isFloat = true;
            text += '.';
            ++pos_;
            digits(text, isDigit);
        }
        if (pos_ < src_.size() && (src_[pos_] == 'e' || src_[pos_] == 'E')) {
            std::size_t k = pos_ + 1;
            if (k < src_.size() && (src_[k] == '+' || src_[k] == '-')) ++k;
            if (k < src_.size() && isDigit(src_[k])) {
                isFloat = true;
                text += src_.substr(pos_, k - pos_);
                pos_ = k;
                digits(text, isDigit);
            }
        }
        if (pos_ < src_.size() && (src_[pos_] == 'j' || src_[pos_] == 'J'))
            fail(column, "complex numbers are not supported");
        if (isFloat) {
            if (!std::isfinite(std::strtod(text.c_str(), nullptr)))
                fail(column, "float literal `" + text + "` is out of range");
            t.kind = Token::Kind::Float;
            t.text = std::move(text);
            return;
        }
        const std::size_t nz = text.find_first_not_of('0');
        if (nz == std::string::npos) {
            text = "0";
        } else {
            if (nz > 0) fail(column, "leading zeros in an integer literal are not Python");
            if (text.size() > 19 || (text.size() == 19 && text > "9223372036854775807"))
                fail(column, "integer literal too large for g2d's 64-bit int");
        }
        t.kind = Token::Kind::Int;
        t.text = std::move(text);
    }

    // `start` is the prefix's offset (or the quote's); pos_ is at the quote.
    void string(Token& t, std::size_t start) {
        std::string prefix(src_.substr(start, pos_ - start));
        bool raw = false, f = false;
        for (char& ch : prefix) {
            ch = static_cast<char>(ch >= 'A' && ch <= 'Z' ? ch - 'A' + 'a' : ch);
            raw = raw || ch == 'r';
            f = f || ch == 'f';
            if (ch == 'b') fail(col(start), "bytes literals are not supported");
        }
        const char q = src_[pos_];
        const bool triple = src_.substr(pos_, 3) == std::string(3, q);
        pos_ += triple ? 3 : 1;
        const std::size_t body = pos_;
        for (;;) {
            if (pos_ >= src_.size() || (!triple && src_[pos_] == '\n')) fail(col(start), "unterminated string");
            if (src_[pos_] == '\\') {
                pos_ += 2;
                continue;
            }
            if (src_[pos_] == q && (!triple || src_.substr(pos_, 3) == std::string(3, q))) break;
            ++pos_;
        }
        const std::string_view text = src_.substr(body, pos_ - body);
        pos_ += triple ? 3 : 1;
        t.column = col(start);
        if (f) {
            t.kind = Token::Kind::FStr;
            t.text = std::string(text);
            t.bodyColumn = col(body);
            t.raw = raw;
        } else {
            t.kind = Token::Kind::Str;
            t.text = raw ? std::string(text) : decodeEscapes(text, t.column);
        }
    }

    void op(Token& t) {
        static constexpr std::string_view kTwo[] = {"**", "//", "==", "!=", "<=", ">=", "<<", ">>", ":=", "->"};
        static constexpr std::string_view kOne = "+-*/%<>()[]{},:.=~&|^@;!";
        t.kind = Token::Kind::Op;
        if (src_.substr(pos_, 3) == "...") {
            t.text = "...";
            pos_ += 3;
            return;
        }
        for (std::string_view two : kTwo) {
            if (src_.substr(pos_, 2) == two) {
                t.text = std::string(two);
                pos_ += 2;
                return;
            }
        }
        if (kOne.find(src_[pos_]) == std::string_view::npos) {
            const unsigned char c = static_cast<unsigned char>(src_[pos_]);
            fail(t.column, c < 0x20 || c >= 0x7F ? std::string("unexpected character")
                                                 : "unexpected character `" + std::string(1, src_[pos_]) + "`");
        }
        t.text = std::string(1, src_[pos_++]);
    }

    std::string_view src_;
    int base_;
    std::size_t pos_ = 0;
};

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
            Parser sub(Lexer(expr, colAt(start)).run(), depth_);
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
        Parser parser(Lexer(source, 0).run(), 0);
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
