#include "g2d/param_parse.hpp"

#include <charconv>
#include <cmath>

namespace g2d::rt {

namespace {

std::optional<double> parseDouble(const std::string& s) {
    double v = 0;
    auto res = std::from_chars(s.data(), s.data() + s.size(), v);
    if (res.ec != std::errc() || res.ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

}  // namespace

std::optional<Value> parseParamValue(ParamType type, const std::string& text, int enumId,
                                     const std::vector<std::string>& enumValues, const std::string& enumName) {
    switch (type) {
    case ParamType::Int: {
        long long v = 0;
        auto res = std::from_chars(text.data(), text.data() + text.size(), v);
        if (res.ec != std::errc() || res.ptr != text.data() + text.size()) return std::nullopt;
        return Value{v};
    }
    case ParamType::Float:
        if (auto d = parseDouble(text)) return Value{*d};
        return std::nullopt;
    case ParamType::Bool:
        if (text == "true") return Value{true};
        if (text == "false") return Value{false};
        return std::nullopt;
    case ParamType::String: return Value{text};
    case ParamType::Vec2:
    case ParamType::Vec3: {
        std::string inner = trim(text);
        if (inner.size() >= 2 && inner.front() == '(' && inner.back() == ')') inner = inner.substr(1, inner.size() - 2);
        std::vector<double> xs;
        for (std::size_t start = 0;;) {
            const auto comma = inner.find(',', start);
            auto x = parseDouble(trim(inner.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
            if (!x) return std::nullopt;
            xs.push_back(*x);
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
        if (type == ParamType::Vec2 && xs.size() == 2) return Value{vec2{xs[0], xs[1]}};
        if (type == ParamType::Vec3 && xs.size() == 3) return Value{vec3{xs[0], xs[1], xs[2]}};
        return std::nullopt;
    }
    case ParamType::Enum: {
        const std::string prefix = enumName + ".";
        const std::string value = !enumName.empty() && text.rfind(prefix, 0) == 0 ? text.substr(prefix.size()) : text;
        for (std::size_t i = 0; i < enumValues.size(); ++i)
            if (enumValues[i] == value) return Value{EnumVal{enumId, static_cast<int>(i)}};
        return std::nullopt;
    }
    }
    return std::nullopt;
}

}  // namespace g2d::rt
