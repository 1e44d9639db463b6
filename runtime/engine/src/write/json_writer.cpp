#include "g2d/json_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "g2d/ops.hpp"

namespace g2d::rt {

namespace {

void writeJsonString(TextOut& out, const std::string& s) {
    out.write('"');
    std::size_t from = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        if (c >= 0x20 && c != '"' && c != '\\') continue;
        out.write(std::string_view(s).substr(from, i - from));
        from = i + 1;
        switch (c) {
        case '"': out.write("\\\""); break;
        case '\\': out.write("\\\\"); break;
        case '\n': out.write("\\n"); break;
        case '\r': out.write("\\r"); break;
        case '\t': out.write("\\t"); break;
        default: {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out.write(buf);
        }
        }
    }
    out.write(std::string_view(s).substr(from));
    out.write('"');
}

void writeNumbers(TextOut& out, std::initializer_list<double> xs) {
    out.write('[');
    bool first = true;
    for (double x : xs) {
        if (!first) out.write(", ");
        first = false;
        out.number(x);
    }
    out.write(']');
}

void writeValue(TextOut& out, const Value& v, const JsonSchema& schema) {
    if (auto* i = std::get_if<long long>(&v)) return out.integer(*i);
    if (auto* d = std::get_if<double>(&v)) return out.number(*d);
    if (auto* b = std::get_if<bool>(&v)) return out.write(*b ? "true" : "false");
    if (auto* s = std::get_if<std::string>(&v)) return writeJsonString(out, *s);
    if (auto* p = std::get_if<vec2>(&v)) return writeNumbers(out, {p->x, p->y});
    if (auto* p = std::get_if<vec3>(&v)) return writeNumbers(out, {p->x, p->y, p->z});
    const auto& e = std::get<EnumVal>(v);
    writeJsonString(out, schema.enumValueNames.at(e.enumId).at(e.index));
}

bool finite(const Value& v) {
    if (const auto* d = std::get_if<double>(&v)) return std::isfinite(*d);
    if (const auto* p = std::get_if<vec2>(&v)) return isFinitePosition(*p);
    if (const auto* p = std::get_if<vec3>(&v)) return isFinitePosition(*p);
    return true;
}

// The element's attributes, `, "name": value` each. JSON has no infinities
// or NaN. Every operation that makes a number checks it, so this only guards
// the file: nothing invalid is ever written.
void writeAttributes(TextOut& out, const AttributeReader& attr, const JsonSchema& schema, ElemClass cls, const char* clsName,
                     std::uint32_t id, int kind) {
    const auto& names = schema.attrNames[kind];
    for (std::size_t a = 0; a < names.size(); ++a) {
        const Value v = attr(cls, id, static_cast<int>(a));
        if (!finite(v))
            throw std::runtime_error(std::string(clsName) + " " + std::to_string(id) + "'s attribute `" + names[a] + "` is " +
                                     toString(v) + ", which JSON cannot hold");
        out.write(", ");
        writeJsonString(out, names[a]);
        out.write(": ");
        writeValue(out, v, schema);
    }
}

// Each edge's multigraph key: how many live edges with the same source and
// target have a lower id. Found per source among its outgoing edges.
std::vector<std::uint32_t> multigraphKeys(const Graph& g) {
    std::vector<std::uint32_t> keys(g.edgeCapacity(), 0);
    std::vector<std::pair<NodeId, EdgeId>> out;   // (target, edge) of one source
    for (NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        out.clear();
        for (EdgeId e = g.firstOut(n); e != kNoId; e = g.nextOut(e))
            if (g.edgeAlive(e)) out.emplace_back(g.target(e), e);
        if (out.size() < 2) continue;
        std::sort(out.begin(), out.end());
        for (std::size_t i = 1; i < out.size(); ++i)
            if (out[i].first == out[i - 1].first) keys[out[i].second] = keys[out[i - 1].second] + 1;
    }
    return keys;
}

// A face's holes (`layout angles`' islands) as `"holes": [[node, ...], ...]`;
// nothing for a face without, so other outputs keep their bytes.
void writeHoles(TextOut& out, std::span<const std::vector<NodeId>> holes) {
    if (holes.empty()) return;
    out.write(", \"holes\": [");
    for (std::size_t h = 0; h < holes.size(); ++h) {
        out.write(h ? ", [" : "[");
        for (std::size_t i = 0; i < holes[h].size(); ++i) {
            if (i) out.write(", ");
            out.integer(holes[h][i]);
        }
        out.write(']');
    }
    out.write(']');
}

}  // namespace

std::string jsonString(const std::string& s) {
    StringOut out;
    writeJsonString(out, s);
    return std::move(out.text());
}

void writeJson(const Graph& g, const JsonSchema& schema, const std::vector<std::pair<std::string, Value>>& graphAttrs,
               TextOut& out, const AttributeReader& reader) {
    const AttributeReader attr = reader ? reader : AttributeReader([&](ElemClass cls, std::uint32_t id, int a) {
        return g.attrOf(cls, id, a);
    });
    out.write("{\"directed\": true, \"multigraph\": true, \"graph\": {");
    for (std::size_t i = 0; i < graphAttrs.size(); ++i) {
        if (i) out.write(", ");
        writeJsonString(out, graphAttrs[i].first);
        out.write(": ");
        writeValue(out, graphAttrs[i].second, schema);
    }
    out.write("},\n\"nodes\": [");
    bool first = true;
    for (NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        const int k = g.nodeKind(n);
        out.write(first ? "\n" : ",\n");
        first = false;
        const Value pos = schema.space3d ? Value{g.pos3(n)} : Value{g.pos(n)};
        if (!finite(pos)) throw std::runtime_error("node " + std::to_string(n) + "'s position is not finite");
        out.write("{\"id\": ");
        out.integer(n);
        out.write(", \"kind\": ");
        writeJsonString(out, schema.kindNames[k]);
        out.write(", \"pos\": ");
        writeValue(out, pos, schema);
        out.write(", \"age\": ");
        out.integer(g.nodeAge(n));
        if (schema.space3d) {
            out.write(", \"radius\": ");
            out.number(g.radius(n));
        }
        writeAttributes(out, attr, schema, ElemClass::Node, "node", n, k);
        out.write('}');
    }
    out.write("],\n\"links\": [");
    first = true;
    const std::vector<std::uint32_t> keys = multigraphKeys(g);
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e) {
        if (!g.edgeAlive(e)) continue;
        const int k = g.edgeKind(e);
        out.write(first ? "\n" : ",\n");
        first = false;
        out.write("{\"source\": ");
        out.integer(g.source(e));
        out.write(", \"target\": ");
        out.integer(g.target(e));
        out.write(", \"key\": ");
        out.integer(keys[e]);
        out.write(", \"id\": ");
        out.integer(e);
        out.write(", \"kind\": ");
        writeJsonString(out, schema.kindNames[k]);
        out.write(", \"directed\": ");
        out.write(g.kinds()[k].directed ? "true" : "false");
        out.write(", \"age\": ");
        out.integer(g.edgeAge(e));
        if (const auto bend = g.edgeBend(e); !bend.empty()) {   // the points between source and target (edge_bends.hpp)
            out.write(", \"bend\": [");
            for (std::size_t i = 0; i < bend.size(); ++i) {
                if (i) out.write(", ");
                writeValue(out, Value{bend[i]}, schema);
            }
            out.write(']');
        }
        writeAttributes(out, attr, schema, ElemClass::Edge, "edge", e, k);
        out.write('}');
    }
    out.write(']');
    // Faces, for grammars that declare a face kind (networkx ignores the key).
    const bool faceKinds = std::any_of(g.kinds().begin(), g.kinds().end(), [](const KindInfo& k) { return k.cls == ElemClass::Face; });
    if (faceKinds) {
        out.write(",\n\"faces\": [");
        first = true;
        for (FaceId f = 0; f < g.faceCapacity(); ++f) {
            if (!g.faceAlive(f)) continue;
            const int k = g.faceKind(f);
            out.write(first ? "\n" : ",\n");
            first = false;
            out.write("{\"id\": ");
            out.integer(f);
            out.write(", \"kind\": ");
            writeJsonString(out, schema.kindNames[k]);
            out.write(", \"corners\": [");
            CornerId c = g.firstCorner(f);
            for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) {
                if (i) out.write(", ");
                out.integer(g.cornerNode(c));
            }
            out.write(']');
            writeHoles(out, g.faceHoles(f));
            out.write(", \"age\": ");
            out.integer(g.faceAge(f));
            writeAttributes(out, attr, schema, ElemClass::Face, "face", f, k);
            out.write('}');
        }
        out.write(']');
    }
    out.write("}\n");
    out.flush();
}

std::string writeJson(const Graph& g, const JsonSchema& schema, const std::vector<std::pair<std::string, Value>>& graphAttrs,
                      const AttributeReader& attr) {
    StringOut out;
    writeJson(g, schema, graphAttrs, out, attr);
    return std::move(out.text());
}

}  // namespace g2d::rt
