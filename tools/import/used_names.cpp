#include "import/used_names.hpp"

#include <cctype>

namespace g2d::import {

namespace {

std::string withoutComments(const std::string& text) {
    std::string out;
    bool inString = false, comment = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') {
            comment = inString = false;
            out += c;
            continue;
        }
        if (comment) continue;
        if (inString) {
            if (c == '\\' && i + 1 < text.size()) out += text[i++];
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            comment = true;
            continue;
        }
        out += c;
    }
    return out;
}

bool word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether `name` occurs in `code` as a whole word.
bool reads(const std::string& code, const std::string& name) {
    for (std::size_t at = code.find(name); at != std::string::npos; at = code.find(name, at + 1)) {
        const bool before = at > 0 && word(code[at - 1]);
        const bool after = at + name.size() < code.size() && word(code[at + name.size()]);
        if (!before && !after) return true;
    }
    return false;
}

}  // namespace

std::set<std::string> usedNames(const std::string& code, const std::vector<std::pair<std::string, std::string>>& declared) {
    std::set<std::string> used;
    std::vector<std::string> frontier{withoutComments(code)};
    while (!frontier.empty()) {
        const std::string text = std::move(frontier.back());
        frontier.pop_back();
        for (const auto& [name, expression] : declared)
            if (!used.count(name) && reads(text, name)) {
                used.insert(name);
                frontier.push_back(withoutComments(expression));
            }
    }
    return used;
}

}  // namespace g2d::import
