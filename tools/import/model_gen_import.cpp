// The original tool's grammar as g2d source (docs/import.md). The tool's
// elements are untyped attribute dictionaries, so the grammar gets one node
// kind and one edge kind holding every attribute; `label` and the other keys
// keep their names, and the tool's conditions become `where` conditions.

#include "import/model_gen_import.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

#include "import/model_gen_catalogue.hpp"
#include "import/model_gen_names.hpp"
#include "import/model_gen_styles.hpp"
#include "import/python_expr.hpp"
#include "import/rule_scope.hpp"
#include "import/line_wrap.hpp"
#include "import/used_names.hpp"

namespace g2d::import {
namespace {

bool isUserKey(const std::string& key) {
    return !key.empty() && key[0] != '.' && key != "x" && key != "y" && key != "new_x" && key != "new_y";
}

// Whether every `or`-part compares attr with a non-empty string: an element
// without the key ("" in g2d) then fails the condition as the tool's does.
bool falseOnEmptyString(const std::string& condition) {
    std::string rest = condition;
    std::size_t at = 0;
    while (true) {
        const std::size_t next = rest.find(" or ", at);
        const std::string part = rest.substr(at, next == std::string::npos ? std::string::npos : next - at);
        auto label = labelTested(part);
        if (!label || label->empty()) return false;
        if (next == std::string::npos) return true;
        at = next + 4;
    }
}

// A Python literal's text ("'0.1mm'", "0", "None"), or nullopt for an expression.
std::optional<MgScalar> pythonLiteral(const std::string& source) {
    std::string s = source;
    while (!s.empty() && s.back() == ' ') s.pop_back();
    while (!s.empty() && s.front() == ' ') s.erase(s.begin());
    MgScalar out;
    if (s.size() >= 2 && (s.front() == '\'' || s.front() == '"') && s.back() == s.front() &&
        s.find(s.front(), 1) == s.size() - 1) {
        out.text = s.substr(1, s.size() - 2);
        out.quoted = true;
        return out;
    }
    if (s == "None") { out.kind = MgScalar::Kind::Null; out.text = "None"; return out; }
    if (s == "True" || s == "False") { out.kind = MgScalar::Kind::Bool; out.text = s; return out; }
    if (lengthInUnits(s) && s.find_first_not_of("0123456789.-+e") == std::string::npos) {
        out.kind = MgScalar::Kind::Float;
        out.text = s;
        return out;
    }
    return std::nullopt;
}

PyType literalType(const MgScalar& s) {
    switch (s.kind) {
        case MgScalar::Kind::Bool: return PyType::Bool;
        case MgScalar::Kind::Int: return PyType::Int;
        case MgScalar::Kind::Float: return PyType::Float;
        case MgScalar::Kind::Null: return PyType::None;
        case MgScalar::Kind::String: break;
    }
    // The tool's files write numbers as strings ('25') and read them with float().
    const std::string& t = s.text;
    if (t == "True" || t == "False") return PyType::Bool;
    if (!t.empty() && t.find_first_not_of("0123456789-+") == std::string::npos && t != "-" && t != "+") return PyType::Int;
    if (!t.empty() && t.find_first_not_of("0123456789.-+e") == std::string::npos && lengthInUnits(t)) return PyType::Float;
    return PyType::String;
}

// A literal value as g2d source of the given type.
// The literal as a value of `type`; nullopt for an int g2d cannot hold.
std::optional<std::string> literalAs(const MgScalar& s, PyType type) {
    switch (type) {
        case PyType::Bool: return isTrue(s) ? "true" : "false";
        case PyType::String: return quoted(s.kind == MgScalar::Kind::Null ? "" : s.text);
        case PyType::Int:
            if (auto v = lengthInUnits(s.text)) {
                const double rounded = std::round(*v * kPixelsPerUnit);
                if (!(std::abs(rounded) < 9.2e18)) return std::nullopt;   // past g2d's 64-bit int
                return std::to_string(static_cast<long long>(rounded));
            }
            return "0";
        default:
            if (s.text == "True" || s.text == "False") return isTrue(s) ? "1" : "0";
            if (auto v = lengthInUnits(s.text); v && s.text.find_first_not_of("0123456789.-+e") == std::string::npos)
                return numberText(*v * kPixelsPerUnit);
            return "0";
    }
}

// svgwrite's pixel paths (`{s.x*35}`) in graph units: the factor goes.
std::string withoutPixelScale(const std::string& source) {
    std::string out;
    for (std::size_t i = 0; i < source.size(); ++i) {
        if (source[i] == '*') {
            std::size_t j = i + 1;
            while (j < source.size() && source[j] == ' ') ++j;
            if (source.compare(j, 2, "35") == 0) {
                std::size_t k = j + 2;
                while (k < source.size() && source[k] == ' ') ++k;
                if (k < source.size() && source[k] == '}') {
                    while (!out.empty() && out.back() == ' ') out.pop_back();
                    i = k - 1;
                    continue;
                }
            }
        }
        out += source[i];
    }
    return out;
}

// `X.attr['.svg_stroke_width']` reads a style property: kept as attribute svg_stroke_width.
std::string styleReadsAsAttributes(const std::string& source) {
    std::string out = source;
    for (const char* from : {"['.svg_", "[\".svg_"}) {
        for (std::size_t at = out.find(from); at != std::string::npos; at = out.find(from, at)) out.erase(at + 2, 1);
    }
    return out;
}

// A line comment quoting the tool's text: a line feed, carriage return or NUL
// in it would end the comment (or the file) for g2d, so they are spelled out.
std::string comment(const std::string& text) {
    std::string out = "// ";
    out.reserve(text.size() + 3);
    for (char c : text) {
        if (c == '\n') out += "\\n";
        else if (c == '\r') out += "\\r";
        else if (c == '\0') out += "\\0";
        else out += c;
    }
    return out;
}

class Importer {
public:
    Importer(const MgGrammar& g, std::string fileName, const G2dNames& names)
        : g_(g), file_(std::move(fileName)), reserved_(withKinds(names.reserved)), notAttributes_(names.notAttributes),
          notStyles_(names.notStyles), ruleNames_(reserved_) {
        nodes_.isNode = true;
        edges_.isNode = false;
    }

    ImportedGrammar run() {
        if (g_.hosts.size() > 1)
            warn(g_.hosts[1].second.line, "only the first host graph is imported (the tool's window runs the first)");
        collectKeys();
        decideDirection();
        readGlobals();
        for (const auto& p : g_.productions) scopes_.push_back(RuleScope::build(p, g_.globals, ruleNames_, consts_, reserved_));
        for (int pass = 0; pass < 2; ++pass) inferExpressionTypes();
        settleCatalogue(nodes_);
        settleCatalogue(edges_);
        writeKinds();
        writeAxiom();
        for (std::size_t i = 0; i < g_.productions.size(); ++i) writeRule(g_.productions[i], scopes_[i]);
        const std::string body = out_.str();   // the header declares the consts it uses
        out_.str("");
        writeHeader(body);
        out_ << body;
        return {wrapLongLines(out_.str()), std::move(warnings_)};
    }

private:
    const MgGrammar& g_;
    std::string file_;
    KindCatalogue nodes_, edges_;
    bool directed_ = false;
    bool mixedDirections_ = false;
    std::vector<ImportWarning> warnings_;
    std::ostringstream out_;
    std::set<std::string> reserved_;     // g2d's names and the imported kinds'
    const std::set<std::string>& notAttributes_;
    const std::set<std::string>& notStyles_;
    NameSet ruleNames_;                  // rules and constants share the global namespace

    static std::set<std::string> withKinds(std::set<std::string> names) {
        names.insert({"Vertex", "Edge"});
        return names;
    }
    std::map<std::string, ConstName> consts_;
    std::vector<RuleScope> scopes_;

    void warn(int line, std::string message) { warnings_.push_back({line, std::move(message)}); }

    KindCatalogue& kindOf(bool isNode) { return isNode ? nodes_ : edges_; }

    const MgGraph& host() const { return g_.hosts.front().second; }

    // ---- what the elements hold -------------------------------------------

    // A key of the tool's that g2d keeps as an attribute: a name g2d can
    // declare (the tool's keys are any text). The others are left out, with a
    // warning the first time.
    // The style property a `.svg_` key sets, if g2d can name it (a keyword cannot follow `style.`).
    std::optional<std::string> styleOf(std::string_view key) const {
        auto prop = stylePropertyOf(key);
        if (prop && notStyles_.count(*prop)) return std::nullopt;
        return prop;
    }
    bool keptKey(const std::string& key) const {
        return isUserKey(key) && isIdentifier(key) && !notAttributes_.count(key);
    }
    void noteRefusedKey(const MgAttribute& a) {
        const bool styleKey = a.key.rfind(".svg_", 0) == 0 || a.key.rfind(".svgx_", 0) == 0;
        if (styleKey && !styleOf(a.key) && refusedKeys_.insert(a.key).second)
            warn(a.line, "`" + a.key + "` names no style property g2d can write: it is left out");
        if (!isUserKey(a.key) || keptKey(a.key) || !refusedKeys_.insert(a.key).second) return;
        warn(a.line, "the attribute key `" + a.key + "` " +
                         (isIdentifier(a.key) ? "is a name g2d reserves" : "is not a g2d name") + ": it is left out");
    }
    std::set<std::string> refusedKeys_;

    void noteLiteral(KindCatalogue& kind, const MgAttribute& a) {
        noteRefusedKey(a);
        if (!keptKey(a.key)) return;
        bool conflict = false;
        auto& attr = kind.add(a.key);
        attr.type = mergeTypes(attr.type, literalType(a.value), conflict);
    }

    void collectKeys() {
        for (bool isNode : {true, false}) {
            const auto& elements = isNode ? host().vertices : host().edges;
            for (const auto& e : elements) for (const auto& a : e.attributes) noteLiteral(kindOf(isNode), a);
        }
        for (const auto& p : g_.productions) {
            for (bool isNode : {true, false})
                for (const auto& e : isNode ? p.mother.vertices : p.mother.edges)
                    for (const auto& a : e.attributes) {
                        noteRefusedKey(a);
                        if (!keptKey(a.key)) continue;
                        auto& attr = kindOf(isNode).add(a.key);
                        attr.usedInCondition = true;
                        if (falseOnEmptyString(a.value.text)) {
                            bool conflict = false;
                            attr.type = mergeTypes(attr.type, PyType::String, conflict);
                        }
                    }
            for (const auto& o : p.options)
                for (bool isNode : {true, false})
                    for (const auto& e : isNode ? o.daughter.vertices : o.daughter.edges)
                        for (const auto& a : e.attributes) {
                            noteRefusedKey(a);
                            if (keptKey(a.key)) kindOf(isNode).add(a.key);
                            if (auto prop = styleOf(a.key); prop && *prop == "tag" && tagOf(a.value.text) != "none")
                                kindOf(isNode).tagVaries = true;
                            for (const char* form : {"attr['.svg_", "attr[\".svg_"}) {
                                for (std::size_t at = a.value.text.find(form); at != std::string::npos;
                                     at = a.value.text.find(form, at + 1)) {
                                    const std::size_t start = at + std::string(form).size();
                                    const std::size_t end = a.value.text.find_first_of("'\"", start);
                                    if (end == std::string::npos) continue;
                                    const std::string prop = a.value.text.substr(start, end - start);
                                    // Which kind sets it decides where it is kept.
                                    if (!styleOf(".svg_" + prop)) continue;   // no property g2d can name
                                    for (bool k : {true, false}) kindOf(k).readStyles.insert(prop);
                                }
                            }
                        }
        }
        for (bool isNode : {true, false})
            for (const auto& e : isNode ? host().vertices : host().edges)
                for (const auto& a : e.attributes)
                    if (auto prop = styleOf(a.key); prop && *prop == "tag" && tagOf(a.value.text) != "none")
                        kindOf(isNode).tagVaries = true;
        for (bool isNode : {true, false}) {
            auto& kind = kindOf(isNode);
            std::set<std::string> kept;
            for (const auto& prop : kind.readStyles)
                if (setsStyle(isNode, prop)) {
                    kept.insert(prop);
                    bool conflict = false;
                    auto& attr = kind.add("svg_" + prop);
                    attr.type = mergeTypes(attr.type, PyType::Float, conflict);
                }
            kind.readStyles = kept;
        }
    }

    bool setsStyle(bool isNode, const std::string& prop) const {
        auto sets = [&](const MgElement& e) {
            for (const auto& a : e.attributes) if (styleOf(a.key) == prop) return true;
            return false;
        };
        for (const auto& e : isNode ? host().vertices : host().edges) if (sets(e)) return true;
        for (const auto& p : g_.productions)
            for (const auto& o : p.options)
                for (const auto& e : isNode ? o.daughter.vertices : o.daughter.edges) if (sets(e)) return true;
        return false;
    }

    // The kind is directed when every mother edge is; otherwise a `.directed`
    // mother edge asks for its direction in a condition (directionCondition).
    void decideDirection() {
        bool anyDirected = false, anyUndirected = false;
        for (const auto& p : g_.productions)
            for (const auto& e : p.mother.edges) {
                const auto* d = e.attribute(".directed");
                (d && isTrue(d->value) ? anyDirected : anyUndirected) = true;
            }
        directed_ = anyDirected && !anyUndirected;
        mixedDirections_ = anyDirected && anyUndirected;
    }

    std::string directionCondition(const RuleScope& scope, const MgElement& e) const {
        const auto* d = e.attribute(".directed");
        if (!mixedDirections_ || !d || !isTrue(d->value)) return "";
        // An undirected edge keeps the orientation it was written in; a
        // zero-length one has no direction and matches neither way.
        return "dot(" + scope.motherName(e.id) + ".direction, " + scope.endName(e, false) + ".pos - " +
               scope.endName(e, true) + ".pos) > 0";
    }

    void readGlobals() {
        for (const auto& gv : g_.globals) {
            PyContext context;
            context.lookup = [&](std::string_view name) -> std::optional<PyBinding> {
                auto it = consts_.find(std::string(name));
                if (it == consts_.end()) return std::nullopt;
                return PyBinding{PyBinding::Kind::Value, it->second.name, it->second.type, true};
            };
            context.attributeType = [](bool, std::string_view) { return PyType::Unknown; };
            PyTranslation t = translatePython(gv.expression, context);
            ConstName c{ruleNames_.take(snakeName(gv.name)), t.ok ? t.type : PyType::Float, t.ok ? t.text : "0", ""};
            if (!t.ok) {
                c.todo = "TODO: " + gv.name + ": " + gv.expression + " (" + t.problem + ")";
                warn(gv.line, "global `" + gv.name + "` cannot be translated: " + t.problem);
            }
            consts_[gv.name] = std::move(c);
        }
    }

    PyContext contextFor(const RuleScope& scope, const ElementScope& element) {
        PyContext context;
        context.lookup = [&scope, element](std::string_view name) { return scope.lookup(name, element); };
        context.attributeType = [this](bool isNode, std::string_view key) {
            const auto* a = kindOf(isNode).find(std::string(key));
            return a ? (a->type == PyType::Unknown ? PyType::Float : a->type) : PyType::Unknown;
        };
        return context;
    }

    void inferExpressionTypes() {
        for (std::size_t i = 0; i < g_.productions.size(); ++i) {
            const auto& p = g_.productions[i];
            RuleScope& scope = scopes_[i];
            for (std::size_t oi = 0; oi < p.options.size(); ++oi) {
                const auto& o = p.options[oi];
                for (bool isNode : {true, false})
                    for (const auto& e : isNode ? o.daughter.vertices : o.daughter.edges)
                        for (const auto& a : e.attributes) {
                            if (!keptKey(a.key)) continue;
                            PyTranslation t = translatePython(styleReadsAsAttributes(a.value.text),
                                                              contextFor(scope, scope.element(oi, e.id, isNode)));
                            if (!t.ok) continue;
                            bool conflict = false;
                            auto& attr = kindOf(isNode).add(a.key);
                            attr.type = mergeTypes(attr.type, t.type, conflict);
                        }
                scope.typeVariables(oi, [&](const std::string& source) {
                    return translatePython(styleReadsAsAttributes(source), contextFor(scope, scope.element(oi, "", true)));
                });
            }
        }
    }

    void settleCatalogue(KindCatalogue& kind) {
        for (auto& attr : kind.attributes) {
            if (attr.type == PyType::Unknown) attr.type = attr.key == "label" ? PyType::String : PyType::Float;
            if (attr.type == PyType::Vec2) {
                warn(0, "attribute `" + attr.key + "` holds a vector, which g2d's attributes cannot: kept as its length");
                attr.type = PyType::Float;
            }
        }
        // Which keys every element has: a condition on a key some element lacks
        // must also ask that the key be set, as the tool's matcher did.
        auto hasAll = [&](const std::vector<MgElement>& elements, const std::string& key) {
            for (const auto& e : elements) if (!e.attribute(key)) return false;
            return true;
        };
        for (auto& attr : kind.attributes) {
            if (!attr.usedInCondition) continue;
            bool everywhere = hasAll(kind.isNode ? host().vertices : host().edges, attr.key);
            for (const auto& p : g_.productions)
                for (const auto& o : p.options) {
                    const auto& elements = kind.isNode ? o.daughter.vertices : o.daughter.edges;
                    for (const auto& e : elements)
                        if (!isKept(o, e.id) && !e.attribute(".helper_node") && !e.attribute(attr.key)) everywhere = false;
                }
            bool allStringTests = attr.type == PyType::String;
            for (const auto& p : g_.productions)
                for (const auto& e : kind.isNode ? p.mother.vertices : p.mother.edges)
                    if (const auto* c = e.attribute(attr.key); c && !falseOnEmptyString(c->value.text)) allStringTests = false;
            attr.setEverywhere = everywhere;
            attr.presenceFlag = !everywhere && !allStringTests;
        }
    }

    static bool isKept(const MgOption& o, const std::string& daughterId) {
        for (const auto& [m, d] : o.mapping) if (d == daughterId) return true;
        return false;
    }

    // ---- writing ------------------------------------------------------------

    void writeHeader(const std::string& body) {
        out_ << comment("Imported by `g2d import` from " + file_ + ",") << "\n"
             << "// a grammar of the original tool of Pogrzebacz 2019 (docs/import.md).\n"
             << "// The tool's elements are untyped, so every node is a Vertex and every edge an\n"
             << "// Edge; its attributes keep their names, its conditions are `where` clauses.\n\n";
        long long all = 0;
        bool hasAll = false;
        for (const auto& [key, n] : g_.maxDerivations)
            if (key == "all") { all = n; hasAll = true; }
        if (hasAll && all > 0) out_ << "limit " << all << ";\n";
        else if (hasAll) out_ << "// The tool's `all: 0`: no global limit (g2d's default stops a runaway).\n";
        else out_ << "limit 500;   // the original tool's default global limit\n";
        for (const auto& [key, n] : g_.maxDerivations)
            if (key != "all" && n > 0) out_ << "priority " << key << " limit " << n << ";\n";
        for (const auto& [id, filter] : g_.svgFilters) out_ << "defs " << quoted(filter) << ";\n";
        out_ << "\n";
        std::vector<std::pair<std::string, std::string>> declared;
        for (const auto& gv : g_.globals) declared.emplace_back(consts_.at(gv.name).name, consts_.at(gv.name).text);
        const std::set<std::string> used = usedNames(body, declared);
        for (const auto& gv : g_.globals) {
            const ConstName& c = consts_.at(gv.name);
            if (!used.count(c.name)) {   // g2d warns of a const nothing reads
                out_ << comment(gv.name + ": " + gv.expression + "   (a global no rule reads: not imported)") << "\n";
                continue;
            }
            if (!c.todo.empty()) out_ << comment(c.todo) << "\n";
            out_ << "const " << c.name << ": " << g2dTypeName(c.type) << " = " << c.text << ";   "
                 << comment(gv.name + ": " + gv.expression) << "\n";
        }
        if (!g_.globals.empty()) out_ << "\n";
    }

    void writeStyle(const KindCatalogue& kind) {
        const bool node = kind.isNode;
        const std::string plain = node ? "\"circle\"" : "\"line\"";
        auto readOr = [&](const std::string& prop, const std::string& fallback) {
            if (!kind.readStyles.count(prop)) return fallback;
            return "svg_" + prop + " >= 0 ? svg_" + prop + " : " + fallback;
        };
        out_ << "    style {\n";
        // The tool drew its graph's parts in the order they were made (docs/import.md).
        out_ << "        z = age;   // the tool's drawing order: creation order\n";
        if (!kind.tagVaries) {
            out_ << "        tag = " << plain << ";\n";
            if (node) out_ << "        r = " << readOr("r", "0.4") << ";\n";
            out_ << "        stroke = \"black\";\n";
            out_ << "        stroke_width = " << readOr("stroke_width", "0.1") << ";   // 1 mm\n";
            if (node) out_ << "        fill = \"none\";\n";
        } else {
            // The tool's defaults differ by tag: none given is a 0.4 circle (or a
            // line) with a 1 mm stroke; a 'circle' is r 1, 0.1 mm; others are SVG's.
            out_ << "        tag = svg_tag == \"\" ? " << plain << " : svg_tag;\n";
            if (node) out_ << "        r = " << readOr("r", "(svg_tag == \"\" ? 0.4 : 1)") << ";\n";
            out_ << "        stroke = svg_tag == \"\" or svg_tag == \"circle\" or svg_tag == \"line\" ? \"black\" : \"none\";\n";
            out_ << "        stroke_width = " << readOr("stroke_width", "(svg_tag == \"circle\" ? 0.01 : 0.1)") << ";\n";
            out_ << "        fill = svg_tag == \"\" or svg_tag == \"circle\" ? \"none\" : \"black\";\n";
        }
        for (const auto& prop : kind.readStyles)
            if (prop != "r" && prop != "stroke_width") out_ << "        " << prop << " = svg_" << prop << ";\n";
        out_ << "    }\n";
    }

    void writeKind(const KindCatalogue& kind) {
        out_ << (kind.isNode ? "node Vertex" : directed_ ? "edge Edge directed" : "edge Edge") << " {\n";
        for (const auto& a : kind.attributes) {
            const bool style = a.key.rfind("svg_", 0) == 0 && kind.readStyles.count(a.key.substr(4));
            out_ << "    " << a.key << ": " << g2dTypeName(a.type) << " = " << (style ? "-1" : defaultLiteral(a.type)) << ";";
            if (style) out_ << "   // the tool's ." << a.key << ", read by rules; -1: not set";
            out_ << "\n";
            if (a.presenceFlag)
                out_ << "    " << presenceFlag(a.key) << ": bool = false;   // the tool's conditions on `" << a.key
                     << "` also asked that it be set\n";
        }
        if (kind.tagVaries) out_ << "    svg_tag: string = \"\";   // the tool's .svg_tag: \"\" is its default drawing\n";
        writeStyle(kind);
        out_ << "}\n\n";
    }

    void writeKinds() {
        writeKind(nodes_);
        writeKind(edges_);
    }

    // One attribute or style assignment of a host element (plain values).
    std::optional<std::string> hostAssignment(const KindCatalogue& kind, const MgAttribute& a, std::vector<std::string>& extra) {
        if (isUserKey(a.key)) {
            if (!keptKey(a.key)) return std::nullopt;
            const auto* attr = kind.find(a.key);
            if (attr->presenceFlag) extra.push_back(presenceFlag(a.key) + " = true");
            const auto value = literalAs(a.value, attr->type);
            if (!value) {
                warn(a.line, "`" + a.key + ": " + a.value.text + "` is past g2d's 64-bit integers: left out");
                return std::nullopt;
            }
            return a.key + " = " + *value;
        }
        auto prop = styleOf(a.key);
        if (!prop) return std::nullopt;
        std::string assignment = styleAssignment(kind, *prop, a.value, std::nullopt);
        if (assignment.empty()) {
            warnTextForNumber(a);
            return std::nullopt;
        }
        return assignment;
    }

    void warnTextForNumber(const MgAttribute& a) {
        warn(a.line, "`" + a.key + ": " + a.value.text + "` is text where the rules read a number: left out");
    }
    void addStyle(std::vector<std::string>& assignments, std::string assignment, const MgAttribute& a) {
        if (assignment.empty()) warnTextForNumber(a);
        else assignments.push_back(std::move(assignment));
    }

    // A style property set from a literal, or from a translated expression.
    std::string styleAssignment(const KindCatalogue& kind, const std::string& prop, const MgScalar& literal,
                                const std::optional<PyTranslation>& expression) {
        const bool kept = kind.readStyles.count(prop) != 0;
        const std::string target = kept ? "svg_" + prop : "style." + prop;
        bool wroteText = false;
        std::string assignment = styleValue(kind, prop, literal, expression, kept, target, wroteText);
        // A kept property is a typed attribute: text for a number cannot go there.
        const CatalogueAttribute* typed = kept ? kind.find("svg_" + prop) : nullptr;
        const bool numeric = typed && (typed->type == PyType::Float || typed->type == PyType::Int);
        if (numeric && (wroteText || (expression && expression->type == PyType::String))) return "";
        return assignment;
    }

    std::string styleValue(const KindCatalogue& kind, const std::string& prop, const MgScalar& literal,
                           const std::optional<PyTranslation>& expression, bool kept, const std::string& target,
                           bool& wroteText) {
        if (prop == "tag") {
            const std::string tag = tagOf(literal.kind == MgScalar::Kind::Null ? "none" : literal.text);
            if (kind.tagVaries) return "svg_tag = " + quoted(tag == "none" ? "none" : tag);
            return "style.tag = " + quoted(tag);
        }
        if (expression) {
            std::string text = expression->text;
            if (isPixelLength(prop) && !kept && expression->type != PyType::String && text.find("svg_") == std::string::npos)
                text = "(" + text + ") / " + numberText(kPixelsPerUnit);
            return target + " = " + text;
        }
        if (isPixelLength(prop))
            if (auto v = lengthInUnits(literal.text)) return target + " = " + numberText(*v);
        if (literal.kind == MgScalar::Kind::Bool) return target + " = " + (isTrue(literal) ? "true" : "false");
        if (prop == "width" || prop == "height" || literal.kind == MgScalar::Kind::Int || literal.kind == MgScalar::Kind::Float)
            if (auto v = lengthInUnits(literal.text); v && literal.text.find_first_not_of("0123456789.-+e") == std::string::npos)
                return target + " = " + numberText(*v * kPixelsPerUnit);
        wroteText = true;
        return target + " = " + quoted(literal.text);
    }

    static std::string block(const std::vector<std::string>& assignments) {
        if (assignments.empty()) return "";
        std::string s = " { ";
        for (std::size_t i = 0; i < assignments.size(); ++i) s += (i ? ", " : "") + assignments[i];
        return s + " }";
    }

    std::string vertexPosition(const MgElement& v) {
        auto coordinate = [&](const char* key) {
            const auto* a = v.attribute(key);
            if (!a) return std::string("0");
            const std::string& text = a->value.text;
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (text.empty() || end != text.c_str() + text.size()) {
                warn(a->line, std::string("the vertex's `") + key + "` is not a number: `" + text + "`; 0 is used");
                return std::string("0");
            }
            // The editor's coordinates come from pixels (a pixel is 0.028
            // units): four decimals keep every one and read better than twelve.
            return numberText(std::round(value * 1e4) / 1e4);
        };
        return "(" + coordinate("x") + ", " + coordinate("y") + ")";
    }

    void writeAxiom() {
        NameSet names(reserved_);
        std::map<std::string, std::string> nameOf;
        out_ << "axiom {\n";
        for (const auto& v : host().vertices) {
            const auto* label = v.attribute("label");
            nameOf[v.id] = names.take(label ? snakeName(label->value.text) : "v");
            std::vector<std::string> assignments, extra;
            for (const auto& a : v.attributes)
                if (auto s = hostAssignment(nodes_, a, extra)) assignments.push_back(*s);
            assignments.insert(assignments.end(), extra.begin(), extra.end());
            out_ << "    " << nameOf[v.id] << ": Vertex at " << vertexPosition(v) << block(assignments) << ";\n";
        }
        for (const auto& e : host().edges) {
            if (!e.vertex1 || !e.vertex2) {
                warn(e.line, "a host edge with a missing end is left out: g2d's edges join two nodes");
                continue;
            }
            std::vector<std::string> assignments, extra;
            for (const auto& a : e.attributes)
                if (auto s = hostAssignment(edges_, a, extra)) assignments.push_back(*s);
            assignments.insert(assignments.end(), extra.begin(), extra.end());
            out_ << "    " << nameOf[*e.vertex1] << " -[Edge" << block(assignments) << "]" << (directed_ ? "-> " : "- ")
                 << nameOf[*e.vertex2] << ";\n";
        }
        out_ << "}\n";
    }

    // ---- rules --------------------------------------------------------------

    void writeCondition(const RuleScope& scope, const MgElement& e, bool isNode, std::vector<std::string>& conditions,
                        std::vector<std::string>& todos) {
        for (const auto& a : e.attributes) {
            if (!isUserKey(a.key)) continue;
            if (!keptKey(a.key)) {
                // Left out, the condition would let the rule match more than the tool's.
                warn(a.line, "the condition `" + a.key + ": " + a.value.text + "` cannot be translated (the key is left out)");
                todos.push_back("TODO: " + scope.motherName(e.id) + " " + a.key + ": " + a.value.text + "   (the key is left out)");
                continue;
            }
            const auto* attr = kindOf(isNode).find(a.key);
            PyContext context = contextFor(scope, ElementScope{});
            context.conditionElement = scope.motherName(e.id);
            context.conditionElementIsNode = isNode;
            context.conditionKey = a.key;
            PyTranslation t = translatePython(a.value.text, context);
            std::string presence = attr && attr->presenceFlag ? context.conditionElement + "." + presenceFlag(a.key) : "";
            if (!t.ok) {
                warn(a.line, "the condition `" + a.key + ": " + a.value.text + "` cannot be translated (" + t.problem +
                                 "); the imported rule matches without it");
                todos.push_back("TODO: " + context.conditionElement + " " + a.key + ": " + a.value.text + "   (" + t.problem + ")");
                if (!presence.empty()) conditions.push_back(presence);
                continue;
            }
            if (t.type == PyType::None) {
                // `None` is never true: the tool's rule never matches.
                warn(a.line, "the condition `" + a.key + ": " + a.value.text + "` is never true: the rule never applies");
                conditions.push_back("false");
                continue;
            }
            if (t.type != PyType::Bool && t.type != PyType::Unknown) {
                // The tool tests a value's truth (`size: True` asks only that the key exist).
                if (t.text == "true") { if (!presence.empty()) conditions.push_back(presence); continue; }
                t.text = "(" + t.text + ") != " + defaultLiteral(t.type);
            }
            conditions.push_back(presence.empty() ? t.text : presence + " and (" + t.text + ")");
        }
    }

    static bool onAnEdge(const MgGraph& g, const std::string& vertexId) {
        return std::any_of(g.edges.begin(), g.edges.end(), [&](const MgElement& e) {
            return (e.vertex1 && *e.vertex1 == vertexId) || (e.vertex2 && *e.vertex2 == vertexId);
        });
    }

    void writeMatch(const MgProduction& p, const RuleScope& scope) {
        out_ << "    match {\n";
        // The tool strips helper nodes from the mother graph, so a helper, like
        // a dangling edge's missing end, takes no part in automatic placement:
        // a wildcard without a sketch position (an `ordered` rule needs one).
        const bool ordered = isOrdered(p);
        for (const auto& v : p.mother.vertices) {
            const std::string& name = scope.motherName(v.id);
            if (scope.isWildcard(v.id) && !onAnEdge(p.mother, v.id)) {
                out_ << "        " << comment("the tool's helper node " + name + ", on no edge: stripped, as the tool does") << "\n";
                continue;
            }
            if (scope.isWildcard(v.id)) {
                out_ << "        " << name << ": *" << (ordered ? " @ " + vertexPosition(v) : "") << ";   // the tool's helper node\n";
                continue;
            }
            std::vector<std::string> conditions, todos;
            writeCondition(scope, v, true, conditions, todos);
            for (const auto& t : todos) out_ << "        " << comment(t) << "\n";
            out_ << "        " << name << ": Vertex @ " << vertexPosition(v);
            for (std::size_t i = 0; i < conditions.size(); ++i) out_ << (i ? " and " : " where ") << conditions[i];
            out_ << ";\n";
        }
        // A dangling edge's missing end: a wildcard that takes no part in the
        // automatic placement (the tool left it out); in an `ordered` rule,
        // sketched on the other end.
        auto vertexById = [&](const std::string& id) -> const MgElement* {
            for (const auto& v : p.mother.vertices) if (v.id == id) return &v;
            return nullptr;
        };
        for (const auto& e : p.mother.edges)
            for (bool first : {true, false}) {
                if (first ? e.vertex1 : e.vertex2) continue;
                const auto& other = first ? e.vertex2 : e.vertex1;
                const MgElement* at = other ? vertexById(*other) : nullptr;
                out_ << "        " << scope.endName(e, first) << ": *"
                     << (ordered ? " @ " + (at ? vertexPosition(*at) : std::string("(0, 0)")) : "") << ";   // a dangling edge's missing end\n";
            }
        for (const auto& e : p.mother.edges) {
            std::vector<std::string> conditions, todos;
            writeCondition(scope, e, false, conditions, todos);
            if (auto direction = directionCondition(scope, e); !direction.empty()) conditions.push_back(direction);
            for (const auto& t : todos) out_ << "        " << comment(t) << "\n";
            out_ << "        " << scope.motherName(e.id) << ": " << scope.endName(e, true) << " -[Edge]"
                 << (directed_ ? "-> " : "- ") << scope.endName(e, false);
            for (std::size_t i = 0; i < conditions.size(); ++i) out_ << (i ? " and " : " where ") << conditions[i];
            out_ << ";\n";
        }
        out_ << "    }\n";
    }

    std::string translatedOrTodo(const std::string& source, const PyContext& context, int line, const std::string& what,
                                 std::vector<std::string>& todos, PyTranslation& t) {
        t = translatePython(source, context);
        if (t.ok && t.type == PyType::None) t = {false, "", PyType::Unknown, "`None` has no g2d value", 0};
        if (t.ok) return t.text;
        warn(line, what + " cannot be translated (" + t.problem + "): left out, marked TODO");
        todos.push_back("TODO: " + what + ": " + source + "   (" + t.problem + ")");
        return "";
    }

    void writeDaughterElement(std::size_t oi, const MgElement& e, bool isNode, const RuleScope& scope,
                              std::vector<std::string>& lines) {
        const ElementScope element = scope.element(oi, e.id, isNode);
        if (element.wildcard || element.helper) return;
        const KindCatalogue& kind = kindOf(isNode);
        const PyContext context = contextFor(scope, element);
        std::vector<std::string> assignments, todos;
        std::optional<std::string> newX, newY, newPos;
        for (const auto& a : e.attributes) {
            PyTranslation t;
            if (a.key == "new_x" || a.key == "new_y" || a.key == ".new_pos") {
                std::string text = translatedOrTodo(styleReadsAsAttributes(a.value.text), context, a.line, a.key, todos, t);
                if (text.empty()) continue;
                const bool wantsVector = a.key == ".new_pos";
                const bool fits = t.type == PyType::Unknown ||
                                  (wantsVector ? t.type == PyType::Vec2 : t.type == PyType::Int || t.type == PyType::Float);
                if (!fits) {   // e.g. a bare word read as text
                    const std::string problem = std::string(wantsVector ? "a position must be a vector" : "a coordinate must be a number") +
                                                ", not a " + std::string(pyTypeName(t.type));
                    warn(a.line, a.key + " cannot be translated (" + problem + "): left out, marked TODO");
                    todos.push_back("TODO: " + a.key + ": " + a.value.text + "   (" + problem + ")");
                    continue;
                }
                (a.key == "new_x" ? newX : a.key == "new_y" ? newY : newPos) = text;
                continue;
            }
            if (isUserKey(a.key)) {
                if (!keptKey(a.key)) continue;
                std::string text =
                    translatedOrTodo(styleReadsAsAttributes(a.value.text), context, a.line, "`" + a.key + "`", todos, t);
                if (text.empty()) continue;
                const auto* attr = kind.find(a.key);
                if (attr->type == PyType::String && t.type != PyType::String && t.type != PyType::Unknown) text = "str(" + text + ")";
                if (t.type == PyType::Vec2 && attr->type != PyType::String) {   // settleCatalogue: a vector is kept as its length
                    text = "length(" + text + ")";
                    t.type = PyType::Float;
                }
                if (attr->type == PyType::Int && (t.type == PyType::Float || t.type == PyType::Bool)) text = "int(" + text + ")";
                if (attr->type == PyType::Float && t.type == PyType::Bool) text = "float(" + text + ")";   // Python's True is 1
                if (attr->type == PyType::Bool && t.type != PyType::Bool && t.type != PyType::Unknown)
                    text = "(" + text + ") != 0";
                assignments.push_back(a.key + " = " + text);
                if (attr->presenceFlag) assignments.push_back(presenceFlag(a.key) + " = true");
                continue;
            }
            auto prop = styleOf(a.key);
            if (!prop) continue;
            std::string source = *prop == "d" ? withoutPixelScale(a.value.text) : a.value.text;
            if (auto literal = pythonLiteral(source)) {
                addStyle(assignments, styleAssignment(kind, *prop, *literal, std::nullopt), a);
                continue;
            }
            std::string text = translatedOrTodo(styleReadsAsAttributes(source), context, a.line, a.key, todos, t);
            if (text.empty()) continue;
            if (t.type == PyType::String && text.size() >= 2 && text.front() == '"' && text.back() == '"' &&
                text.find_first_of("\"\\", 1) == text.size() - 1) {   // an older file's bare word (`.svg_tag: rect`)
                addStyle(assignments,
                         styleAssignment(kind, *prop, MgScalar{text.substr(1, text.size() - 2), MgScalar::Kind::String, true},
                                         std::nullopt),
                         a);
                continue;
            }
            if (*prop == "tag") {
                todos.push_back("TODO: a computed .svg_tag: " + a.value.text);
                warn(a.line, "a computed .svg_tag is not imported: the element keeps its drawing");
                continue;
            }
            addStyle(assignments, styleAssignment(kind, *prop, MgScalar{}, t), a);
        }
        for (const auto& t : todos) lines.push_back(comment(t));
        if (!isNode) {
            std::vector<ScopeWarning> edgeWarnings;
            auto head = scope.daughterEdgeHead(oi, e, directed_, edgeWarnings);
            for (const auto& w : edgeWarnings) warn(w.line, w.message);
            if (!head) return;
            if (head->plain) lines.push_back(head->prefix + block(assignments) + ";");
            else lines.push_back(head->prefix + block(assignments) + head->suffix + ";");
            return;
        }
        std::string at;
        const bool usesPlaced = [&] {
            for (const auto* s : {&newX, &newY, &newPos}) if (*s && (*s)->find("placed") != std::string::npos) return true;
            return false;
        }();
        if (newPos) at = " at " + *newPos;
        else if (newX || newY) {
            const std::string self = element.kept ? element.name + ".pos" : "placed";
            at = " at (" + (newX ? *newX : self + ".x") + ", " + (newY ? *newY : self + ".y") + ")";
            if (element.kept) warn(e.line, "new_x/new_y on a kept vertex stopped the original tool (KeyError); imported as a move");
        }
        const bool sketch = !element.kept && (at.empty() || usesPlaced || (newX && !newY) || (newY && !newX));
        std::string line = element.kept ? element.name : element.name + ": Vertex";
        if (sketch || (element.kept && scope.daughterMoved(oi, e))) line += " @ " + vertexPosition(e);
        line += at + block(assignments) + ";";
        lines.push_back(line);
    }

    static bool isOrdered(const MgProduction& p) {
        for (const auto& [key, value] : p.conditions)
            if (key == ".geometric_ordering" && isTrue(value)) return true;
        return false;
    }

    void writeRule(const MgProduction& p, RuleScope& scope) {
        out_ << "\n// \"" << p.name << "\"\n";
        const bool onlyStripped = std::all_of(p.mother.vertices.begin(), p.mother.vertices.end(), [&](const MgElement& v) {
            return scope.isWildcard(v.id) && !onAnEdge(p.mother, v.id);
        });
        if (p.mother.edges.empty() && onlyStripped) {
            // The tool's matcher starts from an element of the mother graph
            // (thesis Algorithm 5.1, line 3): an empty mother never matches,
            // where g2d's empty match would match at every step.
            out_ << "// Its mother graph is empty, so the tool never applied it: left out.\n";
            warn(p.line, "production `" + p.name + "` has an empty mother graph, which the tool never matches: left out");
            return;
        }
        if (std::all_of(p.options.begin(), p.options.end(), [](const MgOption& o) { return o.weight == 0; })) {
            // The tool's random.choices refuses weights that sum to 0: applying it failed.
            out_ << "// Every daughter has weight 0, which the tool could not choose from: left out.\n";
            warn(p.line, "production `" + p.name + "` has only daughters of weight 0, which the tool cannot choose from: left out");
            return;
        }
        out_ << "rule " << scope.ruleName();
        if (p.priority != 0) out_ << " priority " << p.priority;
        if (isOrdered(p)) out_ << " ordered";
        bool oldest = false;
        for (const auto& o : p.options)
            for (const auto& [key, value] : o.conditions)
                if (key == "generation" && value.text == "oldest") oldest = true;
        if (oldest) out_ << " pick oldest generation";   // the tool's `.generation`, not g2d's age
        out_ << " {\n";
        writeMatch(p, scope);
        std::ostringstream daughters;
        for (std::size_t oi = 0; oi < p.options.size(); ++oi) {
            const auto& o = p.options[oi];
            if (o.weight == 0 && p.options.size() > 1) {
                daughters << "    // a daughter of weight 0, which the tool never chose, is left out\n";
                continue;
            }
            daughters << "    produce";
            if (p.options.size() > 1 || o.weight != 1) daughters << " weight " << numberText(o.weight);
            daughters << " {\n";
            std::vector<std::string> lines;
            for (const auto& v : o.daughter.vertices) writeDaughterElement(oi, v, true, scope, lines);
            for (const auto& e : o.daughter.edges) writeDaughterElement(oi, e, false, scope, lines);
            for (const auto& l : lines) daughters << "        " << l << "\n";
            daughters << "    }\n";
        }
        // The tool declared vectors whether used or not; g2d warns of an unused let.
        std::vector<std::pair<std::string, std::string>> lets;
        for (const auto& let : scope.lets()) lets.emplace_back(let.name, let.text);
        const std::set<std::string> used = usedNames(daughters.str(), lets);
        for (const auto& let : scope.lets()) {
            if (!used.count(let.name)) continue;
            if (!let.todo.empty()) out_ << "    " << comment(let.todo) << "\n";
            out_ << "    let " << let.name << " = " << let.text << ";";
            if (!let.comment.empty()) out_ << "   " << comment(let.comment);
            out_ << "\n";
        }
        for (const auto& w : scope.takeWarnings()) warn(w.line, w.message);
        out_ << daughters.str() << "}\n";
    }
};

}  // namespace

ImportedGrammar importModelGen(const MgGrammar& grammar, const std::string& fileName, const G2dNames& names) {
    return Importer(grammar, fileName, names).run();
}

}  // namespace g2d::import
