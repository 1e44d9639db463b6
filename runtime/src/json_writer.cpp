#include "g2d/json_writer.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "g2d/ops.hpp"

namespace g2d::rt {

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        default:
            if (c < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", c);
                out += buf;
            } else {
                out += static_cast<char>(c);
            }
        }
    }
    return out + "\"";
}

namespace {

std::string jsonValue(const Value& v, const JsonSchema& schema) {
    if (auto* i = std::get_if<long long>(&v)) return std::to_string(*i);
    if (auto* d = std::get_if<double>(&v)) return formatNumber(*d);
    if (auto* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
    if (auto* s = std::get_if<std::string>(&v)) return jsonString(*s);
    if (auto* p = std::get_if<vec2>(&v)) return "[" + formatNumber(p->x) + ", " + formatNumber(p->y) + "]";
    if (auto* p = std::get_if<vec3>(&v)) return "[" + formatNumber(p->x) + ", " + formatNumber(p->y) + ", " + formatNumber(p->z) + "]";
    const auto& e = std::get<EnumVal>(v);
    return jsonString(schema.enumValueNames.at(e.enumId).at(e.index));
}

bool finite(const Value& v) {
    if (const auto* d = std::get_if<double>(&v)) return std::isfinite(*d);
    if (const auto* p = std::get_if<vec2>(&v)) return isFinitePosition(*p);
    if (const auto* p = std::get_if<vec3>(&v)) return isFinitePosition(*p);
    return true;
}

// JSON has no infinities or NaN. Every operation that makes a number checks
// it, so this only guards the file: nothing invalid is ever written.
std::string attributeJson(const Value& v, const JsonSchema& schema, const char* cls, std::uint32_t id, const std::string& name) {
    if (!finite(v))
        throw std::runtime_error(std::string(cls) + " " + std::to_string(id) + "'s attribute `" + name + "` is " +
                                 toString(v) + ", which JSON cannot hold");
    return jsonValue(v, schema);
}

}  // namespace

std::string writeJson(const Graph& g, const JsonSchema& schema,
                      const std::vector<std::pair<std::string, Value>>& graphAttrs, const AttributeReader& reader) {
    const AttributeReader attr = reader ? reader : AttributeReader([&](ElemClass cls, std::uint32_t id, int a) {
        return g.attrOf(cls, id, a);
    });
    std::string out = "{\"directed\": true, \"multigraph\": true, \"graph\": {";
    for (std::size_t i = 0; i < graphAttrs.size(); ++i)
        out += (i ? ", " : "") + jsonString(graphAttrs[i].first) + ": " + jsonValue(graphAttrs[i].second, schema);
    out += "},\n\"nodes\": [";
    bool first = true;
    for (NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        const int k = g.nodeKind(n);
        out += first ? "\n" : ",\n";
        first = false;
        const Value pos = schema.space3d ? Value{g.pos3(n)} : Value{g.pos(n)};
        if (!finite(pos)) throw std::runtime_error("node " + std::to_string(n) + "'s position is not finite");
        out += "{\"id\": " + std::to_string(n) + ", \"kind\": " + jsonString(schema.kindNames[k]) + ", \"pos\": " +
               jsonValue(pos, schema) + ", \"age\": " + std::to_string(g.nodeAge(n));
        if (schema.space3d) out += ", \"radius\": " + formatNumber(g.radius(n));
        for (std::size_t a = 0; a < schema.attrNames[k].size(); ++a)
            out += ", " + jsonString(schema.attrNames[k][a]) + ": " +
                   attributeJson(attr(ElemClass::Node, n, static_cast<int>(a)), schema, "node", n, schema.attrNames[k][a]);
        out += "}";
    }
    out += "],\n\"links\": [";
    first = true;
    std::map<std::pair<NodeId, NodeId>, int> keys;  // multigraph keys per (source, target)
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e) {
        if (!g.edgeAlive(e)) continue;
        const int k = g.edgeKind(e);
        const int key = keys[{g.source(e), g.target(e)}]++;
        out += first ? "\n" : ",\n";
        first = false;
        out += "{\"source\": " + std::to_string(g.source(e)) + ", \"target\": " + std::to_string(g.target(e)) +
               ", \"key\": " + std::to_string(key) + ", \"id\": " + std::to_string(e) + ", \"kind\": " +
               jsonString(schema.kindNames[k]) + ", \"directed\": " + (g.kinds()[k].directed ? "true" : "false") +
               ", \"age\": " + std::to_string(g.edgeAge(e));
        for (std::size_t a = 0; a < schema.attrNames[k].size(); ++a)
            out += ", " + jsonString(schema.attrNames[k][a]) + ": " +
                   attributeJson(attr(ElemClass::Edge, e, static_cast<int>(a)), schema, "edge", e, schema.attrNames[k][a]);
        out += "}";
    }
    out += "]";
    // Faces, for grammars that declare a face kind (networkx ignores the key).
    const bool faceKinds = std::any_of(g.kinds().begin(), g.kinds().end(), [](const KindInfo& k) { return k.cls == ElemClass::Face; });
    if (faceKinds) {
        out += ",\n\"faces\": [";
        first = true;
        for (FaceId f = 0; f < g.faceCapacity(); ++f) {
            if (!g.faceAlive(f)) continue;
            const int k = g.faceKind(f);
            out += first ? "\n" : ",\n";
            first = false;
            out += "{\"id\": " + std::to_string(f) + ", \"kind\": " + jsonString(schema.kindNames[k]) + ", \"corners\": [";
            CornerId c = g.firstCorner(f);
            for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) out += (i ? ", " : "") + std::to_string(g.cornerNode(c));
            out += "], \"age\": " + std::to_string(g.faceAge(f));
            for (std::size_t a = 0; a < schema.attrNames[k].size(); ++a)
                out += ", " + jsonString(schema.attrNames[k][a]) + ": " +
                       attributeJson(attr(ElemClass::Face, f, static_cast<int>(a)), schema, "face", f, schema.attrNames[k][a]);
            out += "}";
        }
        out += "]";
    }
    out += "}\n";
    return out;
}

}  // namespace g2d::rt
