#include "parse/keywords.hpp"

#include <cctype>

#include <antlr4-runtime.h>

#include "G2dLexer.h"

namespace g2d::parse {

const std::vector<std::string>& keywords() {
    static const std::vector<std::string> words = [] {
        antlr4::ANTLRInputStream input("");
        G2dLexer lexer(&input);
        const auto& vocabulary = lexer.getVocabulary();
        std::vector<std::string> out;
        for (std::size_t t = 0; t <= vocabulary.getMaxTokenType(); ++t) {
            const std::string literal = vocabulary.getLiteralName(t);   // with its quotes, or ""
            if (literal.size() < 3) continue;
            const std::string word = literal.substr(1, literal.size() - 2);
            bool identifier = std::isalpha(static_cast<unsigned char>(word[0])) != 0;
            for (char c : word) identifier = identifier && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
            if (identifier) out.push_back(word);
        }
        // Declarations the parser knows by a plain name (G2d.g4: not reserved).
        out.push_back("canvas");
        return out;
    }();
    return words;
}

}  // namespace g2d::parse
