#include "import/model_gen_catalogue.hpp"

namespace g2d::import {

PyType mergeTypes(PyType a, PyType b, bool& conflict) {
    if (a == PyType::Unknown || a == PyType::None) return b == PyType::None ? PyType::Unknown : b;
    if (b == PyType::Unknown || b == PyType::None || a == b) return a;
    auto numeric = [](PyType t) { return t == PyType::Int || t == PyType::Float || t == PyType::Bool; };
    if (numeric(a) && numeric(b)) {
        if (a == PyType::Float || b == PyType::Float) return PyType::Float;
        return PyType::Int;
    }
    conflict = true;
    return (a == PyType::String || b == PyType::String) ? PyType::String : a;
}

std::string g2dTypeName(PyType type) {
    switch (type) {
        case PyType::Bool: return "bool";
        case PyType::Int: return "int";
        case PyType::String: return "string";
        case PyType::Vec2: return "vec2";
        default: return "float";
    }
}

std::string defaultLiteral(PyType type) {
    switch (type) {
        case PyType::Bool: return "false";
        case PyType::Int: return "0";
        case PyType::String: return "\"\"";
        case PyType::Vec2: return "(0, 0)";
        default: return "0";
    }
}

namespace {

// `base`, or `base2`, `base3`, … : the first name not in `taken`, which then takes it.
std::string freeName(const std::string& base, std::set<std::string>& taken) {
    std::string name = base;
    for (int n = 2; taken.count(name); ++n) name = base + std::to_string(n);
    taken.insert(name);
    return name;
}

}  // namespace

void nameAddedAttributes(KindCatalogue& kind, const std::set<std::string>& needFlag) {
    std::set<std::string> taken;
    for (const auto& a : kind.attributes) taken.insert(a.key);
    if (kind.tagVaries) kind.tagAttribute = freeName("svg_tag", taken);
    for (auto& a : kind.attributes)
        if (needFlag.count(a.key)) a.presence = freeName(a.key.rfind("has_", 0) == 0 ? a.key + "_set" : "has_" + a.key, taken);
}

}  // namespace g2d::import
