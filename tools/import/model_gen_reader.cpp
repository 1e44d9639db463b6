// Reads the original tool's YAML (model_gen-format.md) into MgGrammar.
// yaml-cpp keeps a mapping's keys in file order, which the tool's semantics
// need (attribute order, the first host graph).

#include "import/model_gen_grammar.hpp"

#include <yaml-cpp/yaml.h>

#include "g2d/utf8.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>

namespace g2d::import {
namespace {

int lineOf(const YAML::Node& node) { return node.Mark().line + 1; }

// The tool reads each mapping into a Python dict (PyYAML): a key written again
// replaces the earlier value, in the earlier one's place. Every mapping of the
// file is kept so.
template <class Value>
std::string keyOf(const std::pair<std::string, Value>& entry) {
    return entry.first;
}
std::string keyOf(const MgAttribute& a) { return a.key; }
template <class Entry>
std::string keyOf(const Entry& e) { return e.name; }

template <class Entry>
void putInDict(std::vector<Entry>& dict, Entry entry) {
    const std::string key = keyOf(entry);
    auto same = std::find_if(dict.begin(), dict.end(), [&](const Entry& e) { return keyOf(e) == key; });
    if (same != dict.end()) *same = std::move(entry);
    else dict.push_back(std::move(entry));
}

[[noreturn]] void fail(const YAML::Node& node, const std::string& message) {
    throw MgError(lineOf(node), message);
}

bool isInteger(const std::string& s) {
    if (s.empty()) return false;
    std::size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
    if (i == s.size()) return false;
    for (; i < s.size(); ++i) if (s[i] < '0' || s[i] > '9') return false;
    return true;
}

bool isFloat(const std::string& s) {
    if (s.empty()) return false;
    char* end = nullptr;
    std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && s.find_first_of("0123456789") != std::string::npos;
}

// PyYAML's resolution of a plain scalar (the tool wrote and read with it).
MgScalar scalarOf(const YAML::Node& node) {
    if (!node.IsScalar() && !node.IsNull()) fail(node, "expected a single value here");
    MgScalar s;
    if (node.IsNull()) { s.kind = MgScalar::Kind::Null; s.text = "None"; return s; }
    s.text = node.Scalar();
    s.quoted = node.Tag() == "!";
    if (s.quoted) return s;
    if (s.text == "true" || s.text == "True" || s.text == "TRUE") { s.kind = MgScalar::Kind::Bool; s.text = "True"; }
    else if (s.text == "false" || s.text == "False" || s.text == "FALSE") { s.kind = MgScalar::Kind::Bool; s.text = "False"; }
    else if (isInteger(s.text)) s.kind = MgScalar::Kind::Int;
    else if (isFloat(s.text)) s.kind = MgScalar::Kind::Float;
    return s;
}

// The `id` of `element` (which must be a mapping).
std::string idOf(const YAML::Node& element, const char* what) {
    if (!element.IsMap()) fail(element, std::string(what) + " must be a mapping with an id");
    const YAML::Node node = element["id"];
    if (!node || node.IsNull()) fail(element, std::string(what) + " has no id");
    if (!node.IsScalar()) fail(node, std::string(what) + "'s id must be a number");
    return node.Scalar();
}

const YAML::Node required(const YAML::Node& map, const char* key, const char* what) {
    if (!map.IsMap()) fail(map, std::string(what) + " must be a mapping");
    YAML::Node value = map[key];
    if (!value) fail(map, std::string(what) + " has no `" + key + "`");
    return value;
}

std::vector<MgAttribute> attributesOf(const YAML::Node& element) {
    std::vector<MgAttribute> out;
    YAML::Node attr = element["attr"];
    if (!attr || attr.IsNull()) return out;
    if (!attr.IsMap()) fail(attr, "`attr` must be a mapping");
    for (const auto& kv : attr) {
        putInDict(out, MgAttribute{kv.first.Scalar(), scalarOf(kv.second), lineOf(kv.first)});
    }
    return out;
}

std::optional<std::string> endOf(const YAML::Node& edge, const char* key) {
    YAML::Node end = edge[key];
    if (!end || end.IsNull()) return std::nullopt;
    if (!end.IsScalar()) fail(end, std::string("`") + key + "` must be a vertex id");
    return end.Scalar();
}

MgGraph graphOf(const YAML::Node& node, const char* what) {
    if (!node.IsMap()) fail(node, std::string(what) + " must be a mapping with vertices and edges");
    MgGraph g;
    g.line = lineOf(node);
    g.id = node["id"] ? idOf(node, what) : "";
    if (YAML::Node vs = node["vertices"]; vs && !vs.IsNull()) {
        if (!vs.IsSequence()) fail(vs, "`vertices` must be a list");
        for (const auto& v : vs)
            g.vertices.push_back({idOf(v, "a vertex"), attributesOf(v), {}, {}, lineOf(v)});
    }
    if (YAML::Node es = node["edges"]; es && !es.IsNull()) {
        if (!es.IsSequence()) fail(es, "`edges` must be a list");
        for (const auto& e : es)
            g.edges.push_back({idOf(e, "an edge"), attributesOf(e), endOf(e, "vertex1"), endOf(e, "vertex2"), lineOf(e)});
    }
    // Ids name one element each (the tool's loader would make a repeated id
    // the first element again; in one graph that is a corrupt file).
    std::set<std::string> ids;
    for (const auto* list : {&g.vertices, &g.edges})
        for (const auto& e : *list)
            if (!ids.insert(e.id).second)
                throw MgError(e.line, std::string(what) + " has two elements with the id " + e.id);
    auto known = [&](const std::optional<std::string>& id) {
        if (!id) return true;
        for (const auto& v : g.vertices) if (v.id == *id) return true;
        return false;
    };
    for (const auto& e : g.edges)
        if (!known(e.vertex1) || !known(e.vertex2))
            throw MgError(e.line, std::string("an edge of ") + what + " ends at a vertex the graph does not have");
    return g;
}

std::vector<std::pair<std::string, MgScalar>> conditionsOf(const YAML::Node& node) {
    std::vector<std::pair<std::string, MgScalar>> out;
    if (!node || node.IsNull()) return out;
    if (!node.IsMap()) fail(node, "`conditions` must be a mapping");
    for (const auto& kv : node) putInDict(out, std::pair{kv.first.Scalar(), scalarOf(kv.second)});
    return out;
}

// What a graph's id names: a vertex, an edge, or nothing.
enum class ElementKind { None, Vertex, Edge };
ElementKind kindIn(const MgGraph& g, const std::string& id) {
    for (const auto& v : g.vertices) if (v.id == id) return ElementKind::Vertex;
    for (const auto& e : g.edges) if (e.id == id) return ElementKind::Edge;
    return ElementKind::None;
}

// `mapping.dict` keeps mother elements as daughter ones: each key a mother
// vertex or edge, each value a daughter element of the same kind, kept once.
void checkMappingEntry(const YAML::Node& key, const YAML::Node& value, const MgGraph& mother, const MgGraph& daughter,
                       const std::vector<std::pair<std::string, std::string>>& earlier) {
    if (!key.IsScalar()) fail(key, "a key of `mapping.dict` must be a mother element's id");
    if (!value.IsScalar()) fail(value, "a value of `mapping.dict` must be a daughter element's id");
    const std::string m = key.Scalar(), d = value.Scalar();
    const ElementKind mk = kindIn(mother, m), dk = kindIn(daughter, d);
    if (mk == ElementKind::None) fail(key, "the mapping names " + m + ", which is not a vertex or edge of the mother graph");
    if (dk == ElementKind::None)
        fail(value, "the mapping keeps " + m + " as " + d + ", which is not a vertex or edge of the daughter graph");
    if (mk != dk)
        fail(value, "the mapping keeps the mother " + std::string(mk == ElementKind::Vertex ? "vertex " : "edge ") + m +
                        " as the daughter " + (dk == ElementKind::Vertex ? "vertex " : "edge ") + d);
    for (const auto& [em, ed] : earlier) {
        if (em == m) fail(key, "the mapping keeps the mother element " + m + " twice");
        if (ed == d) fail(value, "the mapping keeps both " + em + " and " + m + " as the daughter element " + d);
    }
}

MgOption optionOf(const YAML::Node& node, const MgGraph& mother) {
    MgOption o;
    o.line = lineOf(node);
    o.id = node["id"] ? idOf(node, "a mapping") : "";
    if (YAML::Node w = node["weight"]; w && !w.IsNull()) {
        MgScalar s = scalarOf(w);
        if (s.kind != MgScalar::Kind::Int && s.kind != MgScalar::Kind::Float && !isFloat(s.text))
            fail(w, "a weight must be a number, got `" + s.text + "`");
        o.weight = std::strtod(s.text.c_str(), nullptr);
        if (!std::isfinite(o.weight) || o.weight < 0) fail(w, "a weight must be a non-negative number");
    }
    o.daughter = graphOf(required(node, "daughter_graph", "a mapping"), "the daughter graph");
    if (YAML::Node m = node["mapping"]; m && !m.IsNull()) {
        YAML::Node dict = m["dict"];
        if (dict && !dict.IsNull()) {
            if (!dict.IsMap()) fail(dict, "`mapping.dict` must be a mapping of mother ids to daughter ids");
            for (const auto& kv : dict) {
                checkMappingEntry(kv.first, kv.second, mother, o.daughter, o.mapping);
                o.mapping.emplace_back(kv.first.Scalar(), kv.second.Scalar());
            }
        }
    }
    if (YAML::Node r = node["attr_requirements"]; r && !r.IsNull()) {
        if (!r.IsMap()) fail(r, "`attr_requirements` must be a mapping");
        for (const auto& kv : r) {
            std::vector<MgRequirement> names;
            if (!kv.second.IsMap()) fail(kv.second, "an attribute requirement must map names to mother ids");
            for (const auto& nv : kv.second) putInDict(names, MgRequirement{nv.first.Scalar(), nv.second.Scalar()});
            putInDict(o.requirements, std::pair{kv.first.Scalar(), std::move(names)});
        }
    }
    o.conditions = conditionsOf(node["conditions"]);
    if (YAML::Node vc = node["var_calc_instructions"]; vc && !vc.IsNull()) {
        if (!vc.IsSequence()) fail(vc, "`var_calc_instructions` must be a list");
        for (const auto& item : vc) {
            if (!item.IsSequence() || item.size() != 3)
                fail(item, "a var_calc instruction is [name, expression, 'run' or 'application']");
            std::string when = item[2].Scalar();
            if (when != "run" && when != "application")
                fail(item[2], "a var_calc instruction runs at 'run' or 'application', not '" + when + "'");
            o.varCalc.push_back({item[0].Scalar(), item[1].Scalar(), when, lineOf(item)});
        }
    }
    return o;
}

MgProduction productionOf(const std::string& name, const YAML::Node& node) {
    MgProduction p;
    p.name = name;
    p.line = lineOf(node);
    if (!node.IsMap()) fail(node, "production `" + name + "` must be a mapping");
    if (YAML::Node pr = node["priority"]; pr && !pr.IsNull()) {
        MgScalar s = scalarOf(pr);
        if (!isInteger(s.text)) fail(pr, "a priority must be an integer, got `" + s.text + "`");
        p.priority = std::atoi(s.text.c_str());
    }
    p.conditions = conditionsOf(node["conditions"]);
    if (YAML::Node vs = node["vectors"]; vs && !vs.IsNull()) {
        if (!vs.IsMap()) fail(vs, "`vectors` must be a mapping");
        for (const auto& kv : vs) {
            MgVector v{kv.first.Scalar(), "", std::nullopt, lineOf(kv.first)};
            if (kv.second.IsScalar()) v.from = kv.second.Scalar();
            else if (kv.second.IsSequence() && kv.second.size() == 2) {
                v.from = kv.second[0].Scalar();
                v.to = kv.second[1].Scalar();
            } else fail(kv.second, "a vector is a mother vertex id or a pair of them");
            putInDict(p.vectors, std::move(v));
        }
    }
    p.mother = graphOf(required(node, "mother_graph", "a production"), "the mother graph");
    YAML::Node mappings = required(node, "mappings", "a production");
    if (!mappings.IsSequence() || mappings.size() == 0) fail(mappings, "a production needs at least one mapping (daughter)");
    for (const auto& m : mappings) p.options.push_back(optionOf(m, p.mother));
    return p;
}

// The tool read its files with PyYAML, which takes UTF-8 text of printable
// characters only (tab and line ends aside: no NUL, no other C0 or C1
// control but NEL, no DEL, no U+FFFE/U+FFFF).
void checkCharacters(const std::string& text) {
    int line = 1;
    for (std::size_t i = 0; i < text.size();) {
        std::uint32_t cp = 0;
        const std::size_t n = rt::utf8SequenceLength(text, i, &cp);
        if (n == 0) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned char>(text[i]));
            throw MgError(line, std::string("invalid UTF-8 (byte ") + hex + "): the tool's grammars are UTF-8 text");
        }
        const bool printable = cp == '\t' || cp == '\n' || cp == '\r' || (cp >= 0x20 && cp <= 0x7E) || cp == 0x85 ||
                               (cp >= 0xA0 && cp != 0xFFFE && cp != 0xFFFF);
        if (!printable) {
            char code[12];
            std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(cp));
            throw MgError(line, std::string("the control character ") + code + " is not allowed in YAML text");
        }
        if (cp == '\n') ++line;
        i += n;
    }
}

// An svgwrite filter call {method: {kwargs}} as SVG text.
std::string filterElement(const std::string& id, const YAML::Node& methods) {
    std::string out = "<filter id=\"" + id + "\">";
    if (methods.IsMap())
        for (const auto& m : methods) {
            out += "<" + m.first.Scalar();
            if (m.second.IsMap())
                for (const auto& kv : m.second) out += " " + kv.first.Scalar() + "=\"" + kv.second.Scalar() + "\"";
            out += "/>";
        }
    return out + "</filter>";
}

}  // namespace

std::optional<std::string> labelTested(const std::string& condition) {
    std::string s;
    for (char c : condition) if (c != ' ') s += c;
    if (s.rfind("attr==", 0) != 0 || s.size() < 9) return std::nullopt;
    const char q = s[6];
    if ((q != '\'' && q != '"') || s.back() != q) return std::nullopt;
    std::string label = s.substr(7, s.size() - 8);
    if (label.find_first_of("'\"") != std::string::npos) return std::nullopt;
    return label;
}

MgGrammar readModelGenGrammar(const std::string& yamlText) {
    checkCharacters(yamlText);
    YAML::Node root;
    try {
        root = YAML::Load(yamlText);
    } catch (const YAML::Exception& e) {
        throw MgError(e.mark.line + 1, "not YAML: " + e.msg);
    }
    if (!root.IsMap()) throw MgError(1, "not a grammar of the original tool: expected host_graphs and productions");
    MgGrammar g;
    try {
        YAML::Node hosts = required(root, "host_graphs", "the grammar");
        if (!hosts.IsMap() || hosts.size() == 0) fail(hosts, "`host_graphs` must name at least one graph");
        for (const auto& kv : hosts) putInDict(g.hosts, std::pair{kv.first.Scalar(), graphOf(kv.second, "a host graph")});
        YAML::Node prods = required(root, "productions", "the grammar");
        if (prods.IsMap())
            for (const auto& kv : prods) putInDict(g.productions, productionOf(kv.first.Scalar(), kv.second));
        else if (!prods.IsNull()) fail(prods, "`productions` must be a mapping of names to productions");
        if (YAML::Node gv = root["global_vars"]; gv && !gv.IsNull()) {
            if (!gv.IsMap()) fail(gv, "`global_vars` must be a mapping");
            for (const auto& kv : gv) putInDict(g.globals, MgGlobal{kv.first.Scalar(), scalarOf(kv.second).text, lineOf(kv.first)});
        }
        if (YAML::Node opts = root["options"]; opts && opts.IsMap())
            if (YAML::Node md = opts["max_derivations"]; md && md.IsMap()) {
                g.maxDerivationsLine = lineOf(md);
                for (const auto& kv : md) {
                    MgScalar n = scalarOf(kv.second);
                    if (!isInteger(n.text) || n.text[0] == '-') fail(kv.second, "a step limit must be a non-negative integer");
                    putInDict(g.maxDerivations, std::pair{kv.first.Scalar(), std::atoll(n.text.c_str())});
                }
            }
        if (YAML::Node svg = root["svg"]; svg && svg.IsMap())
            if (YAML::Node pre = svg["preamble"]; pre && pre.IsMap())
                if (YAML::Node filters = pre["filter"]; filters && filters.IsMap())
                    for (const auto& kv : filters)
                        putInDict(g.svgFilters, std::pair{kv.first.Scalar(), filterElement(kv.first.Scalar(), kv.second)});
    } catch (const YAML::Exception& e) {
        throw MgError(e.mark.line + 1, e.msg);
    }
    return g;
}

}  // namespace g2d::import
