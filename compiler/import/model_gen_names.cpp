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

bool isReserved(std::string_view name) {
    static constexpr std::string_view kReserved[] = {
        // keywords (grammar/G2d.g4)
        "and", "around", "at", "axiom", "between", "compound", "const", "defs", "directed", "dpo",
        "edge", "enum", "face", "false", "fn", "for", "import", "in", "insert", "intersect", "layout",
        "let", "limit", "match", "merge", "node", "not", "or", "ordered", "parallel", "param", "pick",
        "priority", "produce", "rule", "sequence", "space", "split", "style", "true", "undirected",
        "weight", "where", "with", "within",
        // types, built-in values and functions, facts
        "int", "float", "bool", "string", "vec2", "vec3", "pi", "tau", "placed",
        "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sqrt", "exp", "log", "pow", "hypot",
        "floor", "ceil", "round", "radians", "degrees", "abs", "sign", "clamp", "min", "max",
        "dot", "cross", "length", "distance", "normalize", "perp_left", "perp_right", "rotate",
        "angle", "lerp", "str", "format", "random", "uniform", "randint", "normal", "choice",
        "pos", "age", "id", "degree", "in_degree", "out_degree", "faces", "direction",
        "Vertex", "Edge"};
    for (auto r : kReserved)
        if (r == name) return true;
    return false;
}

std::string NameSet::take(const std::string& wanted) {
    std::string base = isReserved(wanted) ? wanted + "_" : wanted;
    std::string name = base;
    for (int k = 2; taken_.count(name) != 0; ++k) name = base + std::to_string(k);
    taken_.insert(name);
    return name;
}

}  // namespace g2d::import
