#include "import/model_gen_styles.hpp"

#include "import/model_gen_names.hpp"

#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstdlib>

namespace g2d::import {

std::optional<std::string> stylePropertyOf(std::string_view key) {
    std::string_view prop;
    if (key.rfind(".svg_", 0) == 0) prop = key.substr(5);
    else if (key.rfind(".svgx_", 0) == 0) prop = key.substr(6);
    if (!isIdentifier(prop)) return std::nullopt;
    return std::string(prop);
}

bool isPixelLength(std::string_view property) {
    return property == "stroke_width" || property == "r" || property == "font_size" ||
           property == "rx" || property == "ry";
}

std::optional<double> lengthInUnits(std::string_view text) {
    std::string s(text);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    double scale = 1.0 / kPixelsPerUnit;
    auto unit = [&](std::string_view suffix, double perUnit) {
        if (s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0) {
            s.resize(s.size() - suffix.size());
            scale = perUnit;
            return true;
        }
        return false;
    };
    unit("mm", 0.1) || unit("cm", 1.0) || unit("px", 1.0 / kPixelsPerUnit) || unit("in", 2.54) ||
        unit("pt", 2.54 / 72);
    if (s.empty()) return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return std::nullopt;
    return value * scale;
}

std::string numberText(double value) {
    if (value == 0) return "0";
    // 12 significant digits: unit conversions (0.1 mm → 0.01) print clean.
    char rounded[32];
    std::snprintf(rounded, sizeof rounded, "%.12g", value);
    char buffer[32];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, std::strtod(rounded, nullptr));
    std::string text(buffer, end);
    if (text.find_first_of(".e") == std::string::npos && (text.size() > 15)) text += ".0";
    return text;
}

std::string escapeString(std::string_view s, bool braces) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            case '\r': out += "\\r"; break;
            case '\0': out += "\\0"; break;
            case '{': out += braces ? "{{" : "{"; break;
            case '}': out += braces ? "}}" : "}"; break;
            default: out += c;
        }
    }
    return out;
}

std::string quoted(std::string_view text) { return "\"" + escapeString(text, false) + "\""; }

std::string tagOf(std::string_view toolTag) {
    std::string t(toolTag);
    if (t.size() >= 2 && (t.front() == '\'' || t.front() == '"') && t.back() == t.front()) t = t.substr(1, t.size() - 2);
    for (auto& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (t.empty() || t == "none") return "none";
    return t;
}

}  // namespace g2d::import
