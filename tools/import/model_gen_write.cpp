// The tool's grammar as g2d source, part 2: the header, the kinds with their
// attributes and styles, and the axiom (the first host graph).
#include "import/model_gen_importer.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace g2d::import::detail {

namespace {

// A whole decimal integer of 64 bits (an optional sign), as Python's int() reads a priority.
std::optional<long long> integerKey(const std::string& key) {
    if (key.empty()) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(key.c_str(), &end, 10);
    if (errno != 0 || end != key.c_str() + key.size() || std::isspace(static_cast<unsigned char>(key[0]))) return std::nullopt;
    return v;
}

}  // namespace

void Importer::writeHeader(const std::string& body) {
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
    for (const auto& [key, n] : g_.maxDerivations) {
        if (key == "all" || n <= 0) continue;
        // The tool looks its limits up by priority: a key that is no integer never applies.
        const std::optional<long long> priority = integerKey(key);
        if (!priority) {
            warn(g_.maxDerivationsLine, "the step limit for `" + key + "` names no priority (the tool's are integers): left out");
            continue;
        }
        out_ << "priority " << *priority << " limit " << n << ";\n";
    }
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

void Importer::writeStyle(const KindCatalogue& kind) {
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
        const std::string& tag = kind.tagAttribute;
        // The tool's defaults differ by tag: none given is a 0.4 circle (or a
        // line) with a 1 mm stroke; a 'circle' is r 1, 0.1 mm; others are SVG's.
        out_ << "        tag = " << tag << " == \"\" ? " << plain << " : " << tag << ";\n";
        if (node) out_ << "        r = " << readOr("r", "(" + tag + " == \"\" ? 0.4 : 1)") << ";\n";
        out_ << "        stroke = " << tag << " == \"\" or " << tag << " == \"circle\" or " << tag << " == \"line\" ? \"black\" : \"none\";\n";
        out_ << "        stroke_width = " << readOr("stroke_width", "(" + tag + " == \"circle\" ? 0.01 : 0.1)") << ";\n";
        out_ << "        fill = " << tag << " == \"\" or " << tag << " == \"circle\" ? \"none\" : \"black\";\n";
    }
    for (const auto& prop : kind.readStyles)
        if (prop != "r" && prop != "stroke_width") out_ << "        " << prop << " = svg_" << prop << ";\n";
    out_ << "    }\n";
}

void Importer::writeKind(const KindCatalogue& kind) {
    out_ << (kind.isNode ? "node Vertex" : directed_ ? "edge Edge directed" : "edge Edge") << " {\n";
    for (const auto& a : kind.attributes) {
        const bool style = a.key.rfind("svg_", 0) == 0 && kind.readStyles.count(a.key.substr(4));
        out_ << "    " << a.key << ": " << g2dTypeName(a.type) << " = " << (style ? "-1" : defaultLiteral(a.type)) << ";";
        if (style) out_ << "   // the tool's ." << a.key << ", read by rules; -1: not set";
        out_ << "\n";
        if (!a.presence.empty())
            out_ << "    " << a.presence << ": bool = false;   // the tool's conditions on `" << a.key
                 << "` also asked that it be set\n";
    }
    if (kind.tagVaries) out_ << "    " << kind.tagAttribute << ": string = \"\";   // the tool's .svg_tag: \"\" is its default drawing\n";
    writeStyle(kind);
    out_ << "}\n\n";
}

void Importer::writeKinds() {
    writeKind(nodes_);
    writeKind(edges_);
}

std::optional<std::string> Importer::hostAssignment(const KindCatalogue& kind, const MgAttribute& a, std::vector<std::string>& extra) {
    if (isUserKey(a.key)) {
        if (!keptKey(a.key)) return std::nullopt;
        const auto* attr = kind.find(a.key);
        if (!attr->presence.empty()) extra.push_back(attr->presence + " = true");
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

void Importer::warnTextForNumber(const MgAttribute& a) {
    warn(a.line, "`" + a.key + ": " + a.value.text + "` is text where the rules read a number: left out");
}

void Importer::addStyle(std::vector<std::string>& assignments, std::string assignment, const MgAttribute& a) {
    if (assignment.empty()) warnTextForNumber(a);
    else assignments.push_back(std::move(assignment));
}

std::string Importer::styleAssignment(const KindCatalogue& kind, const std::string& prop, const MgScalar& literal,
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

std::string Importer::styleValue(const KindCatalogue& kind, const std::string& prop, const MgScalar& literal,
                       const std::optional<PyTranslation>& expression, bool kept, const std::string& target,
                       bool& wroteText) {
    if (prop == "tag") {
        const std::string tag = tagOf(literal.kind == MgScalar::Kind::Null ? "none" : literal.text);
        if (kind.tagVaries) return kind.tagAttribute + " = " + quoted(tag == "none" ? "none" : tag);
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

std::string Importer::block(const std::vector<std::string>& assignments) {
    if (assignments.empty()) return "";
    std::string s = " { ";
    for (std::size_t i = 0; i < assignments.size(); ++i) s += (i ? ", " : "") + assignments[i];
    return s + " }";
}

std::string Importer::vertexPosition(const MgElement& v) {
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

void Importer::writeAxiom() {
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

}  // namespace g2d::import::detail
