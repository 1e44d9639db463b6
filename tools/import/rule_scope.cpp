#include "import/rule_scope.hpp"

#include <cctype>
#include <cstdlib>

namespace g2d::import {
namespace {

bool isTrue(const MgAttribute* a) { return a && isTrue(a->value); }

bool isArgName(const std::string& name) {
    if (name.rfind("arg", 0) != 0 || name.size() == 3) return false;
    for (std::size_t i = 3; i < name.size(); ++i)
        if (!std::isdigit(static_cast<unsigned char>(name[i]))) return false;
    return true;
}


std::string literalLabel(const MgElement& e) {
    const MgAttribute* label = e.attribute("label");
    if (!label) return "";
    std::string t = label->value.text;
    if (t.size() >= 2 && (t.front() == '\'' || t.front() == '"') && t.back() == t.front()) return t.substr(1, t.size() - 2);
    return "";
}

std::optional<std::string> testedLabel(const MgElement& e) {
    const MgAttribute* label = e.attribute("label");
    return label ? labelTested(label->value.text) : std::nullopt;
}

double coordinate(const MgElement& v, const char* key) {
    const MgAttribute* a = v.attribute(key);
    return a ? std::strtod(a->value.text.c_str(), nullptr) : 0.0;
}

}  // namespace

RuleScope RuleScope::build(const MgProduction& p, const std::vector<MgGlobal>& globals, NameSet& ruleNames,
                           const std::map<std::string, ConstName>& consts, const std::set<std::string>& reserved) {
    RuleScope s(reserved);
    s.p_ = &p;
    s.consts_ = &consts;
    s.ruleName_ = ruleNames.take(camelName(p.name));
    for (const auto& [tool, c] : consts) s.names_.reserve(c.name);
    (void)globals;

    // Lets first: the tool's names are what its expressions say.
    for (const auto& v : p.vectors) {
        RuleLet let{v.name, s.names_.take(isIdentifier(v.name) ? v.name : snakeName(v.name)), "", PyType::Vec2, "", "", "", v.line};
        s.vectorLet_[v.name] = s.lets_.size();
        s.lets_.push_back(std::move(let));
    }
    for (std::size_t oi = 0; oi < p.options.size(); ++oi)
        for (const auto& vc : p.options[oi].varCalc) {
            if (s.variableLet_.count(vc.name)) {
                if (s.lets_[s.variableLet_[vc.name]].source != vc.expression)
                    s.warnings_.push_back({vc.line, "daughters compute `" + vc.name +
                                                        "` differently; g2d's lets belong to the rule: the first is used"});
                continue;
            }
            RuleLet let{vc.name, s.names_.take(isIdentifier(vc.name) ? vc.name : snakeName(vc.name)), "0",
                        PyType::Unknown, "", "", vc.expression, vc.line};
            if (vc.when == "run") let.comment = "the tool computed it once per run";
            s.variableLet_[vc.name] = s.lets_.size();
            s.lets_.push_back(std::move(let));
        }

    // Mother names: a requirement name bound to one element only, else its label.
    std::map<std::string, std::set<std::string>> idsOfName;
    for (const auto& o : p.options)
        for (const auto& [target, reqs] : o.requirements)
            for (const auto& r : reqs) idsOfName[r.name].insert(r.motherId);
    std::map<std::string, std::string> wanted;
    for (const auto& [name, ids] : idsOfName)
        if (ids.size() == 1 && !isArgName(name) && isIdentifier(name) && name != "old" && name != "self_" &&
            !s.vectorLet_.count(name) && !s.variableLet_.count(name))
            wanted.emplace(*ids.begin(), name);
    auto nameMother = [&](const MgElement& e, bool isNode) {
        std::string name;
        if (auto it = wanted.find(e.id); it != wanted.end()) name = it->second;
        else if (auto label = testedLabel(e); label && !label->empty()) name = snakeName(*label);
        else name = isNode ? "n" : "e";
        s.motherNames_[e.id] = s.names_.take(name);
        s.motherIsNode_[e.id] = isNode;
    };
    for (const auto& v : p.mother.vertices) {
        if (isTrue(v.attribute(".helper_node"))) s.wildcards_.insert(v.id);
        nameMother(v, true);
    }
    for (const auto& e : p.mother.edges) {
        nameMother(e, false);
        for (int end = 1; end <= 2; ++end)
            if (!(end == 1 ? e.vertex1 : e.vertex2)) {
                std::string w = s.names_.take("w");
                s.danglingEnd_[e.id + "/" + std::to_string(end)] = w;
            }
    }

    for (std::size_t oi = 0; oi < p.options.size(); ++oi) {
        const auto& o = p.options[oi];
        std::map<std::string, std::string> kept, fresh;
        for (const auto& [m, d] : o.mapping) kept[d] = m;
        for (bool isNode : {true, false})
            for (const auto& e : isNode ? o.daughter.vertices : o.daughter.edges) {
                if (kept.count(e.id) || (isNode && isTrue(e.attribute(".helper_node")))) continue;
                const std::string label = literalLabel(e);
                fresh[e.id] = s.names_.take(!label.empty() ? snakeName(label) : isNode ? "n" : "e");
            }
        s.keptBy_.push_back(std::move(kept));
        s.newNames_.push_back(std::move(fresh));
    }

    for (const auto& v : p.vectors) {
        RuleLet& let = s.lets_[s.vectorLet_[v.name]];
        auto pos = [&](const std::string& id) -> std::string {
            auto it = s.motherNames_.find(id);
            if (it == s.motherNames_.end() || !s.motherIsNode_[id]) {
                s.warnings_.push_back({v.line, "vector `" + v.name + "` names " + id + ", which is no mother vertex"});
                return "(0, 0)";
            }
            return it->second + ".pos";
        };
        let.text = v.to ? pos(*v.to) + " - " + pos(v.from) : pos(v.from);
        let.comment = v.to ? "the tool's vector " + v.name : "";
    }
    return s;
}

const std::string& RuleScope::motherName(const std::string& id) const {
    static const std::string unknown = "unknown";
    auto it = motherNames_.find(id);
    return it == motherNames_.end() ? unknown : it->second;
}

std::string RuleScope::endName(const MgElement& motherEdge, bool first) const {
    const auto& end = first ? motherEdge.vertex1 : motherEdge.vertex2;
    if (end) return motherName(*end);
    return danglingEnd_.at(motherEdge.id + (first ? "/1" : "/2"));
}

ElementScope RuleScope::element(std::size_t option, const std::string& daughterId, bool isNode) const {
    ElementScope e;
    e.where = daughterId.empty() ? ElementScope::Where::VarCalc : ElementScope::Where::Daughter;
    e.option = option;
    e.daughterId = daughterId;
    e.isNode = isNode;
    if (daughterId.empty()) return e;
    if (auto it = keptBy_[option].find(daughterId); it != keptBy_[option].end()) {
        e.kept = true;
        e.wildcard = wildcards_.count(it->second) != 0;
        e.name = motherName(it->second);
    } else if (auto n = newNames_[option].find(daughterId); n != newNames_[option].end()) {
        e.name = n->second;
    } else if (isNode) {
        e.helper = true;
    }
    return e;
}

std::optional<PyBinding> RuleScope::elementBinding(const std::string& motherId) const {
    auto it = motherNames_.find(motherId);
    if (it == motherNames_.end()) return std::nullopt;
    return PyBinding{PyBinding::Kind::Element, it->second, PyType::Unknown, motherIsNode_.at(motherId)};
}

std::optional<PyBinding> RuleScope::lookup(std::string_view nameView, const ElementScope& where) const {
    const std::string name(nameView);
    auto constant = [&]() -> std::optional<PyBinding> {
        auto it = consts_->find(name);
        if (it == consts_->end()) return std::nullopt;
        return PyBinding{PyBinding::Kind::Value, it->second.name, it->second.type, true};
    };
    auto requirement = [&](const std::string& target) -> std::optional<PyBinding> {
        for (const auto& [t, reqs] : p_->options[where.option].requirements)
            if (t == target)
                for (const auto& r : reqs)
                    if (r.name == name) return elementBinding(r.motherId);
        return std::nullopt;
    };
    auto let = [&](const std::map<std::string, std::size_t>& lets) -> std::optional<PyBinding> {
        auto it = lets.find(name);
        if (it == lets.end()) return std::nullopt;
        const RuleLet& l = lets_[it->second];
        return PyBinding{PyBinding::Kind::Value, l.name, l.type, true};
    };
    if (where.where == ElementScope::Where::Condition) return constant();
    if (where.where == ElementScope::Where::VarCalc) {
        if (auto b = requirement("all")) return b;
        return let(vectorLet_);
    }
    // Daughter attributes: {**own requirements, **vectors, **variables, 'self_', **all, 'old'}, later wins.
    if (name == "old") {
        if (!where.kept) return std::nullopt;
        return PyBinding{PyBinding::Kind::Element, where.name, PyType::Unknown, where.isNode};
    }
    if (auto b = requirement("all")) return b;
    if (name == "self_") {
        if (where.kept) return PyBinding{PyBinding::Kind::Element, where.name, PyType::Unknown, where.isNode};
        return PyBinding{PyBinding::Kind::Placed, "placed", PyType::Vec2, true};
    }
    if (auto b = constant()) return b;
    if (auto b = let(variableLet_)) return b;
    if (auto b = let(vectorLet_)) return b;
    return requirement(where.daughterId);
}

void RuleScope::typeVariables(std::size_t option, const std::function<PyTranslation(const std::string&)>& translate) {
    for (const auto& vc : p_->options[option].varCalc) {
        RuleLet& let = lets_[variableLet_.at(vc.name)];
        if (let.source != vc.expression) continue;
        PyTranslation t = translate(vc.expression);
        if (t.ok) {
            let.text = t.text;
            let.type = t.type;
            let.todo.clear();
        } else {
            let.text = "0";
            let.type = PyType::Float;
            let.todo = "TODO: " + vc.name + " = " + vc.expression + "   (" + t.problem + ")";
        }
    }
}

std::optional<std::string> RuleScope::daughterVertexName(std::size_t option, const std::optional<std::string>& id) const {
    if (!id) return std::nullopt;
    if (auto it = keptBy_[option].find(*id); it != keptBy_[option].end()) return motherName(it->second);
    const auto& o = p_->options[option];
    for (const auto& v : o.daughter.vertices)
        if (v.id == *id && isTrue(v.attribute(".helper_node"))) return std::nullopt;
    if (auto n = newNames_[option].find(*id); n != newNames_[option].end()) return n->second;
    return std::nullopt;
}

std::optional<EdgeHead> RuleScope::daughterEdgeHead(std::size_t option, const MgElement& edge, bool directed,
                                                    std::vector<ScopeWarning>& warnings) const {
    const std::string arrow = directed ? "]-> " : "]- ";
    auto a = daughterVertexName(option, edge.vertex1);
    auto b = daughterVertexName(option, edge.vertex2);
    auto kept = keptBy_[option].find(edge.id);
    if (kept != keptBy_[option].end()) {
        const MgElement* mother = nullptr;
        for (const auto& e : p_->mother.edges) if (e.id == kept->second) mother = &e;
        const std::string ma = endName(*mother, true), mb = endName(*mother, false);
        const std::string name = motherName(kept->second);
        // A helper (or dangling) end stays on the host node it had: the
        // mother's end that the other daughter end was not kept from, else
        // the mother's helper end, else the end in the same place.
        auto helperEnd = [&](const std::string& other, bool first) {
            if (other == ma) return mb;
            if (other == mb) return ma;
            const bool helperA = !mother->vertex1 || wildcards_.count(*mother->vertex1);
            const bool helperB = !mother->vertex2 || wildcards_.count(*mother->vertex2);
            if (helperA != helperB) return helperA ? ma : mb;
            return first ? ma : mb;
        };
        if (!a && !b) a = ma, b = mb;
        else if (!a) a = helperEnd(*b, true);
        else if (!b) b = helperEnd(*a, false);
        if ((*a == ma && *b == mb) || (!directed && *a == mb && *b == ma)) return EdgeHead{true, name, ""};
        return EdgeHead{false, name + ": " + *a + " -[Edge", arrow + *b};
    }
    if (!a || !b) {
        warnings.push_back({edge.line, "a new edge with a missing end (the tool left it dangling) is left out"});
        return std::nullopt;
    }
    return EdgeHead{false, *a + " -[Edge", arrow + *b};
}

bool RuleScope::daughterMoved(std::size_t option, const MgElement& vertex) const {
    auto it = keptBy_[option].find(vertex.id);
    if (it == keptBy_[option].end()) return false;
    for (const auto& m : p_->mother.vertices)
        if (m.id == it->second)
            return coordinate(m, "x") != coordinate(vertex, "x") || coordinate(m, "y") != coordinate(vertex, "y");
    return false;
}

}  // namespace g2d::import
