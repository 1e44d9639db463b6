#include "token_mutator.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <string>
#include <vector>

namespace g2d::fuzz {

namespace {

// Small, seeded and independent of the standard library's engines.
struct Random {
    std::uint64_t state;
    explicit Random(unsigned int seed) : state(seed * 0x9E3779B97F4A7C15ULL + 1) {}
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }
    std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }
};

// Keywords, type and built-in names, operators and edge arrows, and
// numbers at the edges of what the language accepts.
const char* const kDictionary[] = {
    "and", "at", "axiom", "const", "defs", "directed", "edge", "enum", "false", "fn", "import", "let",
    "limit", "match", "node", "not", "or", "ordered", "parallel", "param", "pick", "priority", "produce",
    "rule", "style", "true", "undirected", "weight", "where", "random", "oldest", "int", "float", "bool",
    "string", "vec2", "pi", "tau", "pos", "sqrt", "pow", "rotate", "perp_left", "length", "normalize",
    "uniform", "randint", "choice", "min", "max", "abs", "round", "floor", "smoothstep", "degree", "in_degree", "midpoint",
    "{", "}", "(", ")", "[", "]", ";", ":", ",", ".", "=", "==", "!=", "<", "<=", ">", ">=", "+", "-",
    "*", "/", "%", "?", "!", "&&", "||", "->", "-[", "]->", "]-", "<-[", "-[Seg]->", "_", "*:",
    "0", "1", "-1", "2", "0.5", "1e308", "1e-308", "9223372036854775807", "9223372036854775808",
    "\"\"", "\"x\"", "\n", " ", "style { stroke = \"red\"; }", "where p.n > 0", "not { q: P; p -[E]-> q; }",
};
constexpr std::size_t kDictionarySize = sizeof(kDictionary) / sizeof(kDictionary[0]);

bool isNameChar(unsigned char c) { return std::isalnum(c) || c == '_'; }

std::vector<std::string> tokenize(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> tokens;
    std::size_t i = 0;
    const auto* s = reinterpret_cast<const char*>(data);
    while (i < size) {
        std::size_t j = i + 1;
        const unsigned char c = data[i];
        if (isNameChar(c)) {
            while (j < size && (isNameChar(data[j]) || (std::isdigit(c) && data[j] == '.'))) ++j;
        } else if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            while (j < size && (data[j] == ' ' || data[j] == '\t' || data[j] == '\n' || data[j] == '\r')) ++j;
        } else if (c == '/' && j < size && data[j] == '/') {
            while (j < size && data[j] != '\n') ++j;
        } else if (c == '"') {
            while (j < size && data[j] != '"' && data[j] != '\n') j += data[j] == '\\' ? 2 : 1;
            j = std::min(size, j + 1);
        }
        tokens.emplace_back(s + i, j - i);
        i = j;
    }
    return tokens;
}

std::size_t pickSignificant(const std::vector<std::string>& tokens, Random& rng) {
    // Prefer tokens that are not white space.
    for (int tries = 0; tries < 8; ++tries) {
        const std::size_t i = rng.below(tokens.size());
        if (!std::isspace(static_cast<unsigned char>(tokens[i][0]))) return i;
    }
    return rng.below(tokens.size());
}

}  // namespace

std::size_t mutateTokens(std::uint8_t* data, std::size_t size, std::size_t maxSize, unsigned int seed) {
    Random rng(seed);
    std::vector<std::string> tokens = tokenize(data, size);
    const int rounds = 1 + static_cast<int>(rng.below(3));
    for (int round = 0; round < rounds; ++round) {
        if (tokens.empty()) {
            tokens.emplace_back(kDictionary[rng.below(kDictionarySize)]);
            continue;
        }
        const std::size_t at = pickSignificant(tokens, rng);
        switch (rng.below(7)) {
        case 0: tokens.erase(tokens.begin() + static_cast<std::ptrdiff_t>(at)); break;
        case 1: tokens.insert(tokens.begin() + static_cast<std::ptrdiff_t>(at), tokens[at]); break;
        case 2: std::swap(tokens[at], tokens[pickSignificant(tokens, rng)]); break;
        case 3: tokens[at] = kDictionary[rng.below(kDictionarySize)]; break;
        case 4: tokens[at] = tokens[pickSignificant(tokens, rng)]; break;
        case 5:
            tokens.insert(tokens.begin() + static_cast<std::ptrdiff_t>(at), std::string(kDictionary[rng.below(kDictionarySize)]) + " ");
            break;
        default: {
            // A whole statement (to the next `;`) repeated, or dropped.
            std::size_t end = at;
            while (end < tokens.size() && tokens[end] != ";") ++end;
            end = std::min(tokens.size(), end + 1);
            std::vector<std::string> statement(tokens.begin() + static_cast<std::ptrdiff_t>(at),
                                               tokens.begin() + static_cast<std::ptrdiff_t>(end));
            if (rng.below(2) == 0)
                tokens.erase(tokens.begin() + static_cast<std::ptrdiff_t>(at), tokens.begin() + static_cast<std::ptrdiff_t>(end));
            else
                tokens.insert(tokens.begin() + static_cast<std::ptrdiff_t>(end), statement.begin(), statement.end());
            break;
        }
        }
    }
    std::size_t out = 0;
    for (const auto& t : tokens) {
        const std::size_t n = std::min(t.size(), maxSize - out);
        std::memcpy(data + out, t.data(), n);
        out += n;
        if (out == maxSize) break;
    }
    return out;
}

std::size_t crossOverLines(const std::uint8_t* a, std::size_t sizeA, const std::uint8_t* b, std::size_t sizeB,
                           std::uint8_t* out, std::size_t maxOut, unsigned int seed) {
    Random rng(seed);
    auto lineStart = [&](const std::uint8_t* d, std::size_t size) {
        std::size_t i = rng.below(size + 1);
        while (i > 0 && d[i - 1] != '\n') --i;
        return i;
    };
    const std::size_t cutA = lineStart(a, sizeA);
    const std::size_t fromB = lineStart(b, sizeB);
    std::size_t n = std::min(cutA, maxOut);
    std::memcpy(out, a, n);
    const std::size_t m = std::min(sizeB - fromB, maxOut - n);
    std::memcpy(out + n, b + fromB, m);
    return n + m;
}

}  // namespace g2d::fuzz
