#include "import/python_lexer.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <utility>

#include "g2d/utf8.hpp"

namespace g2d::import::py {

void fail(int column, std::string problem) { throw Fail{std::move(problem), column}; }
void fail(int column, const char* problem) { throw Fail{problem, column}; }

int codePoints(std::string_view text) { return static_cast<int>(rt::codePointCount(text)); }

namespace {

bool isIdentStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isIdentChar(char c) { return isIdentStart(c) || isDigit(c); }

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

}  // namespace

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

namespace {

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

}  // namespace

std::vector<Token> tokenize(std::string_view source, int baseColumn) { return Lexer(source, baseColumn).run(); }

}  // namespace g2d::import::py
