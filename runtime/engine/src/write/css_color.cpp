#include "g2d/css_color.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

namespace g2d::rt {

namespace {

// The CSS named colours (the 147 of SVG 1.1 and rebeccapurple), sorted.
struct NamedColor {
    std::string_view name, hex;
};
constexpr NamedColor kNamedColors[] = {
    {"aliceblue", "f0f8ff"}, {"antiquewhite", "faebd7"}, {"aqua", "00ffff"}, {"aquamarine", "7fffd4"},
    {"azure", "f0ffff"}, {"beige", "f5f5dc"}, {"bisque", "ffe4c4"}, {"black", "000000"},
    {"blanchedalmond", "ffebcd"}, {"blue", "0000ff"}, {"blueviolet", "8a2be2"}, {"brown", "a52a2a"},
    {"burlywood", "deb887"}, {"cadetblue", "5f9ea0"}, {"chartreuse", "7fff00"}, {"chocolate", "d2691e"},
    {"coral", "ff7f50"}, {"cornflowerblue", "6495ed"}, {"cornsilk", "fff8dc"}, {"crimson", "dc143c"},
    {"cyan", "00ffff"}, {"darkblue", "00008b"}, {"darkcyan", "008b8b"}, {"darkgoldenrod", "b8860b"},
    {"darkgray", "a9a9a9"}, {"darkgreen", "006400"}, {"darkgrey", "a9a9a9"}, {"darkkhaki", "bdb76b"},
    {"darkmagenta", "8b008b"}, {"darkolivegreen", "556b2f"}, {"darkorange", "ff8c00"}, {"darkorchid", "9932cc"},
    {"darkred", "8b0000"}, {"darksalmon", "e9967a"}, {"darkseagreen", "8fbc8f"}, {"darkslateblue", "483d8b"},
    {"darkslategray", "2f4f4f"}, {"darkslategrey", "2f4f4f"}, {"darkturquoise", "00ced1"}, {"darkviolet", "9400d3"},
    {"deeppink", "ff1493"}, {"deepskyblue", "00bfff"}, {"dimgray", "696969"}, {"dimgrey", "696969"},
    {"dodgerblue", "1e90ff"}, {"firebrick", "b22222"}, {"floralwhite", "fffaf0"}, {"forestgreen", "228b22"},
    {"fuchsia", "ff00ff"}, {"gainsboro", "dcdcdc"}, {"ghostwhite", "f8f8ff"}, {"gold", "ffd700"},
    {"goldenrod", "daa520"}, {"gray", "808080"}, {"green", "008000"}, {"greenyellow", "adff2f"},
    {"grey", "808080"}, {"honeydew", "f0fff0"}, {"hotpink", "ff69b4"}, {"indianred", "cd5c5c"},
    {"indigo", "4b0082"}, {"ivory", "fffff0"}, {"khaki", "f0e68c"}, {"lavender", "e6e6fa"},
    {"lavenderblush", "fff0f5"}, {"lawngreen", "7cfc00"}, {"lemonchiffon", "fffacd"}, {"lightblue", "add8e6"},
    {"lightcoral", "f08080"}, {"lightcyan", "e0ffff"}, {"lightgoldenrodyellow", "fafad2"}, {"lightgray", "d3d3d3"},
    {"lightgreen", "90ee90"}, {"lightgrey", "d3d3d3"}, {"lightpink", "ffb6c1"}, {"lightsalmon", "ffa07a"},
    {"lightseagreen", "20b2aa"}, {"lightskyblue", "87cefa"}, {"lightslategray", "778899"}, {"lightslategrey", "778899"},
    {"lightsteelblue", "b0c4de"}, {"lightyellow", "ffffe0"}, {"lime", "00ff00"}, {"limegreen", "32cd32"},
    {"linen", "faf0e6"}, {"magenta", "ff00ff"}, {"maroon", "800000"}, {"mediumaquamarine", "66cdaa"},
    {"mediumblue", "0000cd"}, {"mediumorchid", "ba55d3"}, {"mediumpurple", "9370db"}, {"mediumseagreen", "3cb371"},
    {"mediumslateblue", "7b68ee"}, {"mediumspringgreen", "00fa9a"}, {"mediumturquoise", "48d1cc"},
    {"mediumvioletred", "c71585"}, {"midnightblue", "191970"}, {"mintcream", "f5fffa"}, {"mistyrose", "ffe4e1"},
    {"moccasin", "ffe4b5"}, {"navajowhite", "ffdead"}, {"navy", "000080"}, {"oldlace", "fdf5e6"},
    {"olive", "808000"}, {"olivedrab", "6b8e23"}, {"orange", "ffa500"}, {"orangered", "ff4500"},
    {"orchid", "da70d6"}, {"palegoldenrod", "eee8aa"}, {"palegreen", "98fb98"}, {"paleturquoise", "afeeee"},
    {"palevioletred", "db7093"}, {"papayawhip", "ffefd5"}, {"peachpuff", "ffdab9"}, {"peru", "cd853f"},
    {"pink", "ffc0cb"}, {"plum", "dda0dd"}, {"powderblue", "b0e0e6"}, {"purple", "800080"},
    {"rebeccapurple", "663399"}, {"red", "ff0000"}, {"rosybrown", "bc8f8f"}, {"royalblue", "4169e1"},
    {"saddlebrown", "8b4513"}, {"salmon", "fa8072"}, {"sandybrown", "f4a460"}, {"seagreen", "2e8b57"},
    {"seashell", "fff5ee"}, {"sienna", "a0522d"}, {"silver", "c0c0c0"}, {"skyblue", "87ceeb"},
    {"slateblue", "6a5acd"}, {"slategray", "708090"}, {"slategrey", "708090"}, {"snow", "fffafa"},
    {"springgreen", "00ff7f"}, {"steelblue", "4682b4"}, {"tan", "d2b48c"}, {"teal", "008080"},
    {"thistle", "d8bfd8"}, {"tomato", "ff6347"}, {"turquoise", "40e0d0"}, {"violet", "ee82ee"},
    {"wheat", "f5deb3"}, {"white", "ffffff"}, {"whitesmoke", "f5f5f5"}, {"yellow", "ffff00"},
    {"yellowgreen", "9acd32"},
};

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

std::optional<Rgba> hexColor(std::string_view digits) {
    std::vector<int> v;
    for (char c : digits) {
        if (hexDigit(c) < 0) return std::nullopt;
        v.push_back(hexDigit(c));
    }
    Rgba out;
    double* parts[] = {&out.r, &out.g, &out.b, &out.a};
    if (v.size() == 3 || v.size() == 4) {
        for (std::size_t k = 0; k < v.size(); ++k) *parts[k] = (v[k] * 17) / 255.0;
        return out;
    }
    if (v.size() == 6 || v.size() == 8) {
        for (std::size_t k = 0; k < v.size() / 2; ++k) *parts[k] = (v[2 * k] * 16 + v[2 * k + 1]) / 255.0;
        return out;
    }
    return std::nullopt;
}

struct Arg {
    double value = 0;
    bool percent = false;
};

// A function's arguments: numbers, each perhaps a percentage (or `deg`),
// apart by commas, spaces or a slash.
std::optional<std::vector<Arg>> arguments(std::string_view inner) {
    std::vector<Arg> out;
    std::size_t i = 0;
    auto separator = [](char c) { return c == ' ' || c == ',' || c == '/' || c == '\t' || c == '\n'; };
    while (i < inner.size()) {
        if (separator(inner[i])) {
            ++i;
            continue;
        }
        Arg a;
        const char* first = inner.data() + i;
        if (inner[i] == '+') ++first;
        const auto [end, ec] = std::from_chars(first, inner.data() + inner.size(), a.value);
        if (ec != std::errc() || !std::isfinite(a.value)) return std::nullopt;
        i = static_cast<std::size_t>(end - inner.data());
        if (i < inner.size() && inner[i] == '%') a.percent = true, ++i;
        else if (inner.substr(i, 3) == "deg") i += 3;
        if (i < inner.size() && !separator(inner[i])) return std::nullopt;
        out.push_back(a);
    }
    return out;
}

double unit(double v) { return std::clamp(v, 0.0, 1.0); }   // CSS clamps

double alphaOf(const std::vector<Arg>& args) { return args.size() == 4 ? unit(args[3].percent ? args[3].value / 100 : args[3].value) : 1; }

std::optional<Rgba> rgbFunction(const std::vector<Arg>& args) {
    if (args.size() != 3 && args.size() != 4) return std::nullopt;
    auto channel = [](const Arg& a) { return unit(a.percent ? a.value / 100 : a.value / 255); };
    return Rgba{channel(args[0]), channel(args[1]), channel(args[2]), alphaOf(args)};
}

std::optional<Rgba> hslFunction(const std::vector<Arg>& args) {
    if (args.size() != 3 && args.size() != 4) return std::nullopt;
    const double h = std::fmod(std::fmod(args[0].value, 360.0) + 360.0, 360.0) / 360.0;
    const double s = unit(args[1].value / 100), l = unit(args[2].value / 100);
    // CSS Color 4's hslToRgb.
    auto f = [&](double n) {
        const double k = std::fmod(n + h * 12, 12.0);
        const double a = s * std::min(l, 1 - l);
        return l - a * std::max(-1.0, std::min({k - 3, 9 - k, 1.0}));
    };
    return Rgba{f(0), f(8), f(4), alphaOf(args)};
}

}  // namespace

std::optional<Rgba> cssColor(std::string_view text) {
    std::string t;
    for (char c : text) t += c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
    const auto first = t.find_first_not_of(" \t\n\r\f");
    if (first == std::string::npos) return std::nullopt;
    t = t.substr(first, t.find_last_not_of(" \t\n\r\f") - first + 1);
    if (t[0] == '#') return hexColor(std::string_view(t).substr(1));
    const auto open = t.find('(');
    if (open != std::string::npos && t.back() == ')') {
        const std::string name = t.substr(0, open);
        const auto args = arguments(std::string_view(t).substr(open + 1, t.size() - open - 2));
        if (!args) return std::nullopt;
        if (name == "rgb" || name == "rgba") return rgbFunction(*args);
        if (name == "hsl" || name == "hsla") return hslFunction(*args);
        return std::nullopt;
    }
    if (t == "transparent") return Rgba{0, 0, 0, 0};
    const auto it = std::lower_bound(std::begin(kNamedColors), std::end(kNamedColors), t,
                                     [](const NamedColor& c, const std::string& name) { return c.name < name; });
    if (it != std::end(kNamedColors) && it->name == t) return hexColor(it->hex);
    return std::nullopt;
}

}  // namespace g2d::rt
