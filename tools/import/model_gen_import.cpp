// The original tool's grammar as g2d source (docs/import.md). The tool's
// elements are untyped attribute dictionaries, so the grammar gets one node
// kind and one edge kind holding every attribute; `label` and the other keys
// keep their names, and the tool's conditions become `where` conditions.

#include "import/model_gen_importer.hpp"

#include <cmath>
#include <cstdlib>

namespace g2d::import {
namespace detail {

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

ImportedGrammar Importer::run() {
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

std::optional<std::string> Importer::styleOf(std::string_view key) const {
    auto prop = stylePropertyOf(key);
    if (prop && notStyles_.count(*prop)) return std::nullopt;
    return prop;
}

bool Importer::keptKey(const std::string& key) const {
    return isUserKey(key) && isIdentifier(key) && !notAttributes_.count(key) && !styleAttributes_.count(key);
}

void Importer::noteRefusedKey(const MgAttribute& a) {
    const bool styleKey = a.key.rfind(".svg_", 0) == 0 || a.key.rfind(".svgx_", 0) == 0;
    if (styleKey && !styleOf(a.key) && refusedKeys_.insert(a.key).second)
        warn(a.line, "`" + a.key + "` names no style property g2d can write: it is left out");
    if (!isUserKey(a.key) || keptKey(a.key) || !refusedKeys_.insert(a.key).second) return;
    if (styleAttributes_.count(a.key)) {
        warn(a.line, "the attribute key `" + a.key + "` is the name the tool's ." + a.key + " is kept under, which rules read: "
                     "the key is left out");
        return;
    }
    warn(a.line, "the attribute key `" + a.key + "` " +
                     (isIdentifier(a.key) ? "is a name g2d reserves" : "is not a g2d name") + ": it is left out");
}

void Importer::noteLiteral(KindCatalogue& kind, const MgAttribute& a) {
    noteRefusedKey(a);
    if (!keptKey(a.key)) return;
    bool conflict = false;
    auto& attr = kind.add(a.key);
    attr.type = mergeTypes(attr.type, literalType(a.value), conflict);
}

std::set<std::string> Importer::stylesReadBack() const {
    std::set<std::string> props;
    for (const auto& p : g_.productions)
        for (const auto& o : p.options)
            for (bool isNode : {true, false})
                for (const auto& e : isNode ? o.daughter.vertices : o.daughter.edges)
                    for (const auto& a : e.attributes)
                        for (const char* form : {"attr['.svg_", "attr[\".svg_"})
                            for (std::size_t at = a.value.text.find(form); at != std::string::npos;
                                 at = a.value.text.find(form, at + 1)) {
                                const std::size_t start = at + std::string(form).size();
                                const std::size_t end = a.value.text.find_first_of("'\"", start);
                                if (end == std::string::npos) continue;
                                const std::string prop = a.value.text.substr(start, end - start);
                                if (styleOf(".svg_" + prop)) props.insert(prop);   // else no property g2d can name
                            }
    return props;
}

void Importer::collectKeys() {
    // A style the rules read back is kept as attribute svg_<prop>: a key of
    // the tool's elements with that name cannot be kept beside it.
    for (const auto& prop : stylesReadBack())
        if (setsStyle(true, prop) || setsStyle(false, prop)) styleAttributes_.insert("svg_" + prop);
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
                    }
    }
    // Which kind sets a style read back decides where it is kept.
    for (const auto& prop : stylesReadBack())
        for (bool k : {true, false}) kindOf(k).readStyles.insert(prop);
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

bool Importer::setsStyle(bool isNode, const std::string& prop) const {
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

void Importer::decideDirection() {
    bool anyDirected = false, anyUndirected = false;
    for (const auto& p : g_.productions)
        for (const auto& e : p.mother.edges) {
            const auto* d = e.attribute(".directed");
            (d && isTrue(d->value) ? anyDirected : anyUndirected) = true;
        }
    directed_ = anyDirected && !anyUndirected;
    mixedDirections_ = anyDirected && anyUndirected;
}

std::string Importer::directionCondition(const RuleScope& scope, const MgElement& e) const {
    const auto* d = e.attribute(".directed");
    if (!mixedDirections_ || !d || !isTrue(d->value)) return "";
    // An undirected edge keeps the orientation it was written in; a
    // zero-length one has no direction and matches neither way.
    return "dot(" + scope.motherName(e.id) + ".direction, " + scope.endName(e, false) + ".pos - " +
           scope.endName(e, true) + ".pos) > 0";
}

void Importer::readGlobals() {
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

PyContext Importer::contextFor(const RuleScope& scope, const ElementScope& element) {
    PyContext context;
    context.lookup = [&scope, element](std::string_view name) { return scope.lookup(name, element); };
    context.attributeType = [this](bool isNode, std::string_view key) {
        const auto* a = kindOf(isNode).find(std::string(key));
        return a ? (a->type == PyType::Unknown ? PyType::Float : a->type) : PyType::Unknown;
    };
    return context;
}

void Importer::inferExpressionTypes() {
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

void Importer::settleCatalogue(KindCatalogue& kind) {
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
    std::set<std::string> needFlag;
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
        if (!everywhere && !allStringTests) needFlag.insert(attr.key);
    }
    nameAddedAttributes(kind, needFlag);
}

bool Importer::isKept(const MgOption& o, const std::string& daughterId) {
    for (const auto& [m, d] : o.mapping) if (d == daughterId) return true;
    return false;
}

}  // namespace detail

ImportedGrammar importModelGen(const MgGrammar& grammar, const std::string& fileName, const G2dNames& names) {
    return detail::Importer(grammar, fileName, names).run();
}


}  // namespace g2d::import
