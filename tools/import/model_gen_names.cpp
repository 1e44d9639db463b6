#include "import/model_gen_names.hpp"

#include <cctype>

namespace g2d::import {
namespace {

bool alnum(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }

}  // namespace

std::string camelName(std::string_view text) {
    std::string out;
    bool upper = true;
    for (char c : text) {
        if (!alnum(c)) { upper = true; continue; }
        out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
        upper = false;
    }
    if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "Rule" + out;
    return out;
}

bool isIdentifier(std::string_view text) {
    if (text.empty() || (text[0] >= '0' && text[0] <= '9')) return false;
    for (char c : text)
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) return false;
    return true;
}

std::string snakeName(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (alnum(c)) {
            out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        } else if (!out.empty() && out.back() != '_') {
            out += '_';
        }
    }
    while (!out.empty() && out.back() == '_') out.pop_back();
    if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "n" + out;
    return out;
}

std::string NameSet::take(const std::string& wanted) {
    std::string base = reserved_->count(wanted) ? wanted + "_" : wanted;
    std::string name = base;
    for (int k = 2; taken_.count(name) != 0; ++k) name = base + std::to_string(k);
    taken_.insert(name);
    return name;
}

}  // namespace g2d::import
