#include "g2d/grammar_run.hpp"

#include "g2d/draw_items.hpp"
#include "g2d/graph.hpp"

namespace g2d::rt {

// Out of line: grammar_run.hpp only declares DrawItem and Graph.
std::vector<DrawItem> GrammarRun::drawItems() {
    return rt::drawItems(graph(), [this](ElemClass cls, std::uint32_t id, DrawItem& out) { drawItem(cls, id, out); });
}

namespace {

// Why `value` is outside `p`'s range ("" when within it, or p has none).
std::string outsideRange(const ParamSpec& p, const Value& value) {
    if (!p.min || !p.max) return "";
    double v = 0;
    if (const auto* i = std::get_if<long long>(&value)) v = static_cast<double>(*i);
    else if (const auto* d = std::get_if<double>(&value)) v = *d;
    else return "";
    if (v >= *p.min && v <= *p.max) return "";
    return "parameter `" + p.name + "` must be from " + formatNumber(*p.min) + " to " + formatNumber(*p.max) +
           " (the range its declaration gives), not " + toString(value);
}

// "an int", "a float", "a Mode".
std::string withArticle(const std::string& typeName) {
    const bool vowel = !typeName.empty() && std::string("aeiouAEIOU").find(typeName[0]) != std::string::npos;
    return (vowel ? "an " : "a ") + typeName;
}

}  // namespace

std::optional<Value> parameterValue(const ParamSpec& p, const std::string& text, std::string& why) {
    auto v = parseParamValue(p.type, text, p.enumId, p.enumValues, p.typeName);
    if (!v) {
        std::string hint = p.type == ParamType::Vec2   ? " (write x,y or (x, y))"
                           : p.type == ParamType::Vec3 ? " (write x,y,z or (x, y, z))"
                           : p.type == ParamType::Bool ? " (write true or false)"
                                                       : "";
        if (p.type == ParamType::Enum) {
            hint = " (one of";
            for (const auto& e : p.enumValues) hint += " " + e;
            hint += ")";
        }
        why = "parameter `" + p.name + "`: expected " + withArticle(p.typeName) + ", got `" + text + "`" + hint;
        return std::nullopt;
    }
    why = outsideRange(p, *v);
    if (!why.empty()) return std::nullopt;
    return v;
}

}  // namespace g2d::rt
