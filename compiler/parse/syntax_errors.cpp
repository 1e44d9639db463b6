#include "parse/syntax_errors.hpp"

#include <algorithm>
#include <set>

#include "G2dLexer.h"
#include "diag/suggest.hpp"
#include "g2d/utf8.hpp"

namespace g2d {

namespace {

// The default-channel token `offset` tokens from `t` (negative: before), or
// null (the parser's stream holds every token: parse() fills it first).
antlr4::Token* neighbour(antlr4::Parser* parser, antlr4::Token* t, int offset) {
    auto* stream = parser ? dynamic_cast<antlr4::BufferedTokenStream*>(parser->getInputStream()) : nullptr;
    if (!stream || !t || t->getTokenIndex() == static_cast<size_t>(-1)) return nullptr;
    long i = static_cast<long>(t->getTokenIndex());
    const int step = offset < 0 ? -1 : 1;
    for (int left = offset < 0 ? -offset : offset; left > 0;) {
        i += step;
        if (i < 0 || i >= static_cast<long>(stream->size())) return nullptr;
        if (stream->get(static_cast<size_t>(i))->getChannel() == antlr4::Token::DEFAULT_CHANNEL) --left;
    }
    antlr4::Token* n = stream->get(static_cast<size_t>(i));
    return n->getType() == antlr4::Token::EOF ? nullptr : n;
}

// Whether `t` stands in a `where` condition: a `where` before it in its statement.
bool inCondition(antlr4::Parser* parser, antlr4::Token* t) {
    for (int k = 1; k < 64; ++k) {
        antlr4::Token* p = neighbour(parser, t, -k);
        if (!p || p->getText() == ";" || p->getText() == "{" || p->getText() == "}") return false;
        if (p->getText() == "where") return true;
    }
    return false;
}

// Advice for the mistakes people make, appended to the message ("" for none):
// `=` to compare, `+=`, Python's `a if c else b`, a misspelt declaration keyword.
std::string mistakeHint(antlr4::Parser* parser, antlr4::Token* offending, const std::string& expectedWords) {
    if (!offending || offending->getType() == antlr4::Token::EOF) return "";
    const std::string text = offending->getText();
    antlr4::Token* next = neighbour(parser, offending, 1);
    antlr4::Token* prev = neighbour(parser, offending, -1);
    if (text == "=" && inCondition(parser, offending)) return "; to compare, write `==`";
    if ((text == "+" || text == "-" || text == "*" || text == "/") && next && next->getText() == "=" &&
        expectedWords.find("`=`") != std::string::npos) {
        const std::string name = prev && prev->getType() == G2dLexer::ID ? prev->getText() : "attr";
        // The element whose block this is: the name before its `{`.
        std::string element = "x";
        for (int k = 1; k < 64; ++k) {
            antlr4::Token* p = neighbour(parser, offending, -k);
            if (!p || p->getText() == ";" || p->getText() == "}") break;
            if (p->getText() != "{") continue;
            if (antlr4::Token* e = neighbour(parser, p, -1); e && e->getType() == G2dLexer::ID) element = e->getText();
            break;
        }
        return "; g2d has no `" + text + "=`: write `" + name + " = " + element + "." + name + " " + text +
               " …` (expressions read the value before the step)";
    }
    // `face F directed;`: a face kind's one option is a word, and not that one.
    if (antlr4::Token* kw = neighbour(parser, offending, -2); kw && kw->getText() == "face" && expectedWords == "`;`, `{` or a name")
        return "; a face kind may be `oriented`, and only edge kinds are `directed` or `undirected`";
    if (text == "," && expectedWords == "`)`") {
        // `Kind(all t, x)`: a face over all turns takes nothing else.
        antlr4::Token* every = neighbour(parser, offending, -2);
        antlr4::Token* open = neighbour(parser, offending, -3);
        if (every && every->getText() == "all" && open && open->getText() == "(")
            return "; a face over all turns (`all " + prev->getText() + "`) has no other corners";
        return "; a vector has two or three components: `(x, y)` or `(x, y, z)`";
    }
    // `to` is a plain name, so the parser asks for "a name" where it is missing.
    if (expectedWords == "a name") {
        antlr4::Token* first = nullptr;
        for (int k = 1; k < 64; ++k) {
            antlr4::Token* p = neighbour(parser, offending, -k);
            if (!p || p->getText() == ";" || p->getText() == "}") break;
            first = p;
        }
        if (first && first->getText() == "canvas") return "; a canvas is written `canvas (x0, y0) to (x1, y1);`";
    }
    if (offending->getType() == G2dLexer::ID && (text == "if" || text == "else"))
        return "; a conditional expression is written `condition ? a : b`";
    if (offending->getType() == G2dLexer::ID && expectedWords.rfind("a declaration", 0) == 0)
        return suggest(text, {"node", "edge", "face", "axiom", "rule", "param", "const", "enum", "fn", "import", "limit",
                              "priority", "defs", "space", "merge", "sequence", "canvas"});
    return "";
}

}  // namespace

std::string describeToken(const antlr4::Token* t) {
    if (!t) return "end of file";
    switch (t->getType()) {
    case antlr4::Token::EOF: return "end of file";
    case G2dLexer::ID: return "name `" + t->getText() + "`";
    case G2dLexer::INT: return "integer `" + t->getText() + "`";
    case G2dLexer::FLOAT: return "number `" + t->getText() + "`";
    case G2dLexer::STRING: return "string " + t->getText();
    case G2dLexer::UNTERMINATED_STRING: return "an unterminated string";
    case G2dLexer::UNTERMINATED_COMMENT: return "an unterminated comment";
    case G2dLexer::ERRCHAR: return "unexpected character `" + t->getText() + "`";
    default: return "`" + t->getText() + "`";
    }
}

std::string describeExpected(const antlr4::misc::IntervalSet& expected,
                             const antlr4::dfa::Vocabulary& vocabulary) {
    std::set<size_t> types;
    for (const auto& iv : expected.getIntervals())
        for (ssize_t t = iv.a; t <= iv.b; ++t) types.insert(static_cast<size_t>(t));
    std::vector<std::string> words;
    auto hasLiteral = [&](const char* lit) {
        for (size_t t : types)
            if (vocabulary.getLiteralName(t) == lit) return true;
        return false;
    };
    // At the top level, the parser expects any declaration.
    if (hasLiteral("'rule'") && hasLiteral("'axiom'") && hasLiteral("'node'"))
        return "a declaration (`node`, `edge`, `face`, `axiom`, `rule`, `param`, `const`, `enum`, `fn`, `import`, `limit`, "
               "`priority`, `defs`, `space`, `merge`, `sequence` or `canvas`)";
    // The tokens that can start an expression are summarised in one word.
    // `merge` is a keyword that may also be a name (a parameter's): where a
    // name is expected, it is one of the names.
    if (types.count(G2dLexer::ID))
        for (auto it = types.begin(); it != types.end();) {
            if (vocabulary.getLiteralName(*it) == "'merge'") it = types.erase(it);
            else ++it;
        }
    const bool expression = types.count(G2dLexer::INT) && types.count(G2dLexer::FLOAT) &&
                            types.count(G2dLexer::STRING) && types.count(G2dLexer::ID);
    if (expression) {
        words.push_back("an expression");
        for (size_t t : {size_t(G2dLexer::INT), size_t(G2dLexer::FLOAT), size_t(G2dLexer::STRING),
                         size_t(G2dLexer::ID)})
            types.erase(t);
        for (const char* lit : {"'('", "'-'", "'+'", "'!'", "'not'", "'true'", "'false'"})
            for (auto it = types.begin(); it != types.end();) {
                if (vocabulary.getLiteralName(*it) == lit) it = types.erase(it);
                else ++it;
            }
    }
    for (size_t t : types) {
        if (t == static_cast<size_t>(antlr4::Token::EOF)) { words.push_back("end of file"); continue; }
        if (t == G2dLexer::ID) { words.push_back("a name"); continue; }
        if (t == G2dLexer::INT) { words.push_back("an integer"); continue; }
        if (t == G2dLexer::FLOAT) { words.push_back("a number"); continue; }
        if (t == G2dLexer::STRING) { words.push_back("a string"); continue; }
        std::string lit = vocabulary.getLiteralName(t);
        if (lit.size() >= 2 && lit.front() == '\'') words.push_back("`" + lit.substr(1, lit.size() - 2) + "`");
    }
    if (words.empty()) return "";
    if (words.size() > 10) {   // a rule's nine options still read as a list
        words.resize(10);
        words.push_back("…");
    }
    std::string out;
    for (size_t i = 0; i < words.size(); ++i) {
        if (i > 0) out += (i + 1 == words.size()) ? " or " : ", ";
        out += words[i];
    }
    return out;
}

void SyntaxErrorListener::syntaxError(antlr4::Recognizer* recognizer, antlr4::Token* offending,
                                      size_t line, size_t charPositionInLine, const std::string&,
                                      std::exception_ptr) {
    // One error per line: ANTLR's recovery tends to cascade.
    if (count_ > 0 && line == lastLine_) return;
    ++count_;
    lastLine_ = line;
    Span span{file_, static_cast<std::uint32_t>(line), static_cast<std::uint32_t>(charPositionInLine + 1),
              static_cast<std::uint32_t>(line), 0};
    if (offending && offending->getType() != antlr4::Token::EOF) {
        const std::string text = offending->getText();
        const auto width = static_cast<std::uint32_t>(rt::codePointCount(std::string_view(text).substr(0, text.find('\n'))));
        span.endCol = span.col + std::max<std::uint32_t>(width, 1);
    }
    // A missing `;` or `}` at the end of a line is reported right after the
    // last token of that line, where it belongs, not at the next line's start.
    const bool lexical = offending && (offending->getType() == G2dLexer::ERRCHAR ||
                                       offending->getType() == G2dLexer::UNTERMINATED_STRING ||
                                       offending->getType() == G2dLexer::UNTERMINATED_COMMENT);
    std::string expectedWords;
    if (auto* parser = dynamic_cast<antlr4::Parser*>(recognizer); parser && !lexical)
        expectedWords = describeExpected(parser->getExpectedTokens(), parser->getVocabulary());
    const bool expectsCloser = expectedWords.find("`;`") != std::string::npos ||
                               expectedWords.find("`}`") != std::string::npos ||
                               expectedWords.find("`)`") != std::string::npos;
    if (auto* parser = dynamic_cast<antlr4::Parser*>(recognizer); parser && offending && expectsCloser) {
        auto* stream = dynamic_cast<antlr4::BufferedTokenStream*>(parser->getInputStream());
        const auto index = offending->getTokenIndex();
        if (stream && index != static_cast<size_t>(-1) && index > 0) {
            antlr4::Token* prev = nullptr;
            for (size_t i = index; i-- > 0;) {
                antlr4::Token* t = stream->get(i);
                if (t->getChannel() == antlr4::Token::DEFAULT_CHANNEL) { prev = t; break; }
            }
            if (prev && prev->getLine() < offending->getLine()) {
                std::string text = prev->getText();
                const auto nl = text.rfind('\n');
                const auto width = static_cast<std::uint32_t>(
                    rt::codePointCount(nl == std::string::npos ? std::string_view(text) : std::string_view(text).substr(nl + 1)));
                const auto startCol = nl == std::string::npos ? prev->getCharPositionInLine() : 0;
                std::uint32_t lineNo = static_cast<std::uint32_t>(prev->getLine());
                if (nl != std::string::npos)
                    lineNo += static_cast<std::uint32_t>(std::count(text.begin(), text.end(), '\n'));
                span = Span{file_, lineNo, static_cast<std::uint32_t>(startCol + width + 1), lineNo,
                            static_cast<std::uint32_t>(startCol + width + 2)};
            }
        }
    }
    std::string found = describeToken(offending);
    std::string message;
    if (offending) {
        int type = static_cast<int>(offending->getType());
        if (type == G2dLexer::UNTERMINATED_STRING) message = "unterminated string (missing closing `\"`)";
        else if (type == G2dLexer::UNTERMINATED_COMMENT) message = "unterminated comment (missing `*/`)";
        else if (type == G2dLexer::ERRCHAR && offending->getText() == "]")
            message = "unexpected character `]` (an edge arrow ends with `]->` or `]-`)";
        else if (type == G2dLexer::ERRCHAR && offending->getText() == "'")
            message = "unexpected character `'` (strings are written in double quotes: \"…\")";
        else if (type == G2dLexer::ERRCHAR) message = "unexpected character `" + offending->getText() + "`";
    }
    // Edge arrows: say what an arrow looks like rather than ANTLR's guess.
    if (message.empty() && offending && !lexical) {
        auto* parser = dynamic_cast<antlr4::Parser*>(recognizer);
        auto* stream = parser ? dynamic_cast<antlr4::BufferedTokenStream*>(parser->getInputStream()) : nullptr;
        const auto index = offending->getTokenIndex();
        antlr4::Token* prev = (stream && index != static_cast<size_t>(-1) && index > 0) ? stream->get(index - 1) : nullptr;
        const std::string text = offending->getText();
        if (prev && (prev->getText() == "-[" || prev->getText() == "<-[")) {
            message = "expected an edge kind name after `" + prev->getText() + "`, found " + found;
        } else if (prev && prev->getType() == G2dLexer::ID && (text == "-" || text == "->" || text == "<")) {
            message = "expected an edge arrow (`-[Kind]->`, `<-[Kind]-` or `-[Kind]-`), found " + found;
        }
    }
    if (message.empty()) {
        message = expectedWords.empty() ? "unexpected " + found : "expected " + expectedWords + ", found " + found;
        if (!lexical) message += mistakeHint(dynamic_cast<antlr4::Parser*>(recognizer), offending, expectedWords);
    }
    diags_.error(span, message);
}

}  // namespace g2d
