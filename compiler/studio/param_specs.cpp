#include "studio/param_specs.hpp"

#include <variant>

namespace g2d::studio {

namespace {

const char* typeWord(rt::ParamType type) {
    switch (type) {
        case rt::ParamType::Int: return "int";
        case rt::ParamType::Float: return "float";
        case rt::ParamType::Bool: return "bool";
        case rt::ParamType::String: return "string";
        case rt::ParamType::Vec2: return "vec2";
        case rt::ParamType::Vec3: return "vec3";
        case rt::ParamType::Enum: return "enum";
    }
    return "string";
}

// A value as the page sends it back (run_request.cpp reads it as -D text).
nlohmann::json valueJson(const rt::Value& v, const rt::ParamSpec& spec) {
    return std::visit(
        [&](const auto& x) -> nlohmann::json {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, rt::vec2>) return {x.x, x.y};
            else if constexpr (std::is_same_v<T, rt::vec3>) return {x.x, x.y, x.z};
            else if constexpr (std::is_same_v<T, rt::EnumVal>)
                return x.index >= 0 && std::size_t(x.index) < spec.enumValues.size() ? nlohmann::json(spec.enumValues[x.index])
                                                                                     : nlohmann::json();
            else return x;
        },
        v);
}

}  // namespace

nlohmann::json paramSpecsJson(const std::vector<rt::ParamSpec>& specs) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& spec : specs) {
        nlohmann::json p = {{"name", spec.name}, {"type", typeWord(spec.type)}, {"type_name", spec.typeName},
                            {"default", valueJson(spec.defaultValue, spec)}};
        if (spec.type == rt::ParamType::Enum) p["values"] = spec.enumValues;
        if (spec.min) p["min"] = *spec.min;   // the declaration's range (`in 1..10 step 1`): a slider
        if (spec.max) p["max"] = *spec.max;
        if (spec.step) p["step"] = *spec.step;
        out.push_back(std::move(p));
    }
    return out;
}

}  // namespace g2d::studio
