#pragma once
// One production of the original tool, seen from g2d: the names of its mother
// and daughter elements, its lets (vectors and var_calc instructions), and
// what a bare name in one of its Python expressions stands for, as the tool's
// evaluation environments define it (model_gen-format.md §5.2, §6.2, §6.5).

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "import/model_gen_grammar.hpp"
#include "import/model_gen_names.hpp"
#include "import/python_expr.hpp"

namespace g2d::import {

struct ConstName {            // a global_vars entry as a g2d const
    std::string name;
    PyType type = PyType::Unknown;
    std::string text;
    std::string todo;         // non-empty when it could not be translated
};

struct RuleLet {
    std::string toolName;
    std::string name;
    std::string text;
    PyType type = PyType::Unknown;
    std::string comment;
    std::string todo;
    std::string source;       // a var_calc expression, translated once the attribute types are known
    int line = 0;
};

// Where an expression is evaluated.
struct ElementScope {
    enum class Where { Condition, VarCalc, Daughter } where = Where::Condition;
    std::size_t option = 0;
    std::string daughterId;
    bool isNode = true;
    bool kept = false;
    bool wildcard = false;
    bool helper = false;      // a daughter's helper node: the host node at a kept edge's helper end, not a new vertex
    std::string name;         // the element's g2d name
};

struct ScopeWarning {
    int line;
    std::string message;
};

struct EdgeHead {             // `name: a -[Edge` + assignments + `]-> b`, or a kept edge `name`
    bool plain = false;
    std::string prefix, suffix;
};

class RuleScope {
public:
    static RuleScope build(const MgProduction& p, const std::vector<MgGlobal>& globals, NameSet& ruleNames,
                           const std::map<std::string, ConstName>& consts, const std::set<std::string>& reserved);

    const std::string& ruleName() const { return ruleName_; }
    const std::string& motherName(const std::string& id) const;
    bool isWildcard(const std::string& motherId) const { return wildcards_.count(motherId) != 0; }
    // The g2d name of a mother edge's first or second end.
    std::string endName(const MgElement& motherEdge, bool first) const;

    ElementScope element(std::size_t option, const std::string& daughterId, bool isNode) const;
    std::optional<PyBinding> lookup(std::string_view name, const ElementScope& where) const;

    // Types the var_calc lets by translating them (called again as attribute types settle).
    void typeVariables(std::size_t option, const std::function<PyTranslation(const std::string&)>& translate);
    const std::vector<RuleLet>& lets() const { return lets_; }

    std::optional<EdgeHead> daughterEdgeHead(std::size_t option, const MgElement& edge, bool directed,
                                             std::vector<ScopeWarning>& warnings) const;
    bool daughterMoved(std::size_t option, const MgElement& vertex) const;
    std::vector<ScopeWarning> takeWarnings() { return std::move(warnings_); }

private:
    const MgProduction* p_ = nullptr;
    const std::map<std::string, ConstName>* consts_ = nullptr;
    std::string ruleName_;
    explicit RuleScope(const std::set<std::string>& reserved) : names_(reserved) {}
    NameSet names_;
    std::map<std::string, std::string> motherNames_;                // mother id → name
    std::map<std::string, bool> motherIsNode_;
    std::set<std::string> wildcards_;                               // mother vertex ids
    std::map<std::string, std::string> danglingEnd_;                // "edge id/1" → wildcard name
    std::vector<std::map<std::string, std::string>> keptBy_;        // per option: daughter id → mother id
    std::vector<std::map<std::string, std::string>> newNames_;      // per option: daughter id → name
    std::vector<RuleLet> lets_;
    std::map<std::string, std::size_t> vectorLet_, variableLet_;    // tool name → index in lets_
    std::vector<ScopeWarning> warnings_;

    std::optional<PyBinding> elementBinding(const std::string& motherId) const;
    std::optional<std::string> daughterVertexName(std::size_t option, const std::optional<std::string>& id) const;
};

}  // namespace g2d::import
