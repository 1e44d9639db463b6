// The tool's grammar as g2d source, part 3: each production as a rule, its
// mother graph as the match with `where` conditions, its daughters.
#include "import/model_gen_importer.hpp"

namespace g2d::import::detail {

void Importer::writeCondition(const RuleScope& scope, const MgElement& e, bool isNode, std::vector<std::string>& conditions,
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
        std::string presence = attr && !attr->presence.empty() ? context.conditionElement + "." + attr->presence : "";
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

bool Importer::onAnEdge(const MgGraph& g, const std::string& vertexId) {
    return std::any_of(g.edges.begin(), g.edges.end(), [&](const MgElement& e) {
        return (e.vertex1 && *e.vertex1 == vertexId) || (e.vertex2 && *e.vertex2 == vertexId);
    });
}

void Importer::writeMatch(const MgProduction& p, const RuleScope& scope) {
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

std::string Importer::translatedOrTodo(const std::string& source, const PyContext& context, int line, const std::string& what,
                             std::vector<std::string>& todos, PyTranslation& t) {
    t = translatePython(source, context);
    if (t.ok && t.type == PyType::None) t = {false, "", PyType::Unknown, "`None` has no g2d value", 0};
    if (t.ok) return t.text;
    warn(line, what + " cannot be translated (" + t.problem + "): left out, marked TODO");
    todos.push_back("TODO: " + what + ": " + source + "   (" + t.problem + ")");
    return "";
}

void Importer::writeDaughterElement(std::size_t oi, const MgElement& e, bool isNode, const RuleScope& scope,
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
            if (!attr->presence.empty()) assignments.push_back(attr->presence + " = true");
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

bool Importer::isOrdered(const MgProduction& p) {
    for (const auto& [key, value] : p.conditions)
        if (key == ".geometric_ordering" && isTrue(value)) return true;
    return false;
}

void Importer::writeRule(const MgProduction& p, RuleScope& scope) {
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

}  // namespace g2d::import::detail
