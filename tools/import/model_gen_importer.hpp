#pragma once
// The importer of model_gen_import.cpp, shared by its parts: what the tool's
// elements hold and the kinds they make (model_gen_import.cpp), the header,
// kinds, styles and axiom (model_gen_write.cpp), and the rules
// (model_gen_rules.cpp). Internal to the importer.
#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "import/model_gen_catalogue.hpp"
#include "import/model_gen_names.hpp"
#include "import/model_gen_styles.hpp"
#include "import/python_expr.hpp"
#include "import/rule_scope.hpp"
#include "import/line_wrap.hpp"
#include "import/used_names.hpp"
#include "import/model_gen_import.hpp"

namespace g2d::import::detail {

// A key the grammar's author wrote (not the tool's `.x`, position or bookkeeping keys).
bool isUserKey(const std::string& key);
// Whether every `or`-part compares attr with a non-empty string: an element
// without the key ("" in g2d) then fails the condition as the tool's does.
bool falseOnEmptyString(const std::string& condition);
// A Python literal's text ("'0.1mm'", "0", "None"), or nullopt for an expression.
std::optional<MgScalar> pythonLiteral(const std::string& source);
PyType literalType(const MgScalar& s);
std::optional<std::string> literalAs(const MgScalar& s, PyType type);
// svgwrite's pixel paths (`{s.x*35}`) in graph units: the factor goes.
std::string withoutPixelScale(const std::string& source);
// `X.attr['.svg_stroke_width']` reads a style property: kept as attribute svg_stroke_width.
std::string styleReadsAsAttributes(const std::string& source);
// A line comment quoting the tool's text, its line feeds, CRs and NULs spelled out.
std::string comment(const std::string& text);

class Importer {
public:
    Importer(const MgGrammar& g, std::string fileName, const G2dNames& names)
        : g_(g), file_(std::move(fileName)), reserved_(withKinds(names.reserved)), notAttributes_(names.notAttributes),
          notStyles_(names.notStyles), ruleNames_(reserved_) {
        nodes_.isNode = true;
        edges_.isNode = false;
    }

    ImportedGrammar run();

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
    std::optional<std::string> styleOf(std::string_view key) const;
    bool keptKey(const std::string& key) const;
    void noteRefusedKey(const MgAttribute& a);
    std::set<std::string> refusedKeys_;
    std::set<std::string> styleAttributes_;   // svg_<prop> of each style the rules read back (kept as an attribute)

    void noteLiteral(KindCatalogue& kind, const MgAttribute& a);

    // The style properties daughters read back (`X.attr['.svg_stroke_width']`) that g2d can name.
    std::set<std::string> stylesReadBack() const;
    void collectKeys();

    bool setsStyle(bool isNode, const std::string& prop) const;

    // The kind is directed when every mother edge is; otherwise a `.directed`
    // mother edge asks for its direction in a condition (directionCondition).
    void decideDirection();

    std::string directionCondition(const RuleScope& scope, const MgElement& e) const;

    void readGlobals();

    PyContext contextFor(const RuleScope& scope, const ElementScope& element);

    void inferExpressionTypes();

    void settleCatalogue(KindCatalogue& kind);

    static bool isKept(const MgOption& o, const std::string& daughterId);

    // ---- writing ------------------------------------------------------------

    void writeHeader(const std::string& body);

    void writeStyle(const KindCatalogue& kind);

    void writeKind(const KindCatalogue& kind);

    void writeKinds();

    // One attribute or style assignment of a host element (plain values).
    std::optional<std::string> hostAssignment(const KindCatalogue& kind, const MgAttribute& a, std::vector<std::string>& extra);

    void warnTextForNumber(const MgAttribute& a);
    void addStyle(std::vector<std::string>& assignments, std::string assignment, const MgAttribute& a);

    // A style property set from a literal, or from a translated expression.
    std::string styleAssignment(const KindCatalogue& kind, const std::string& prop, const MgScalar& literal,
                                const std::optional<PyTranslation>& expression);

    std::string styleValue(const KindCatalogue& kind, const std::string& prop, const MgScalar& literal,
                           const std::optional<PyTranslation>& expression, bool kept, const std::string& target,
                           bool& wroteText);

    static std::string block(const std::vector<std::string>& assignments);

    std::string vertexPosition(const MgElement& v);

    void writeAxiom();

    // ---- rules --------------------------------------------------------------

    void writeCondition(const RuleScope& scope, const MgElement& e, bool isNode, std::vector<std::string>& conditions,
                        std::vector<std::string>& todos);

    static bool onAnEdge(const MgGraph& g, const std::string& vertexId);

    void writeMatch(const MgProduction& p, const RuleScope& scope);

    std::string translatedOrTodo(const std::string& source, const PyContext& context, int line, const std::string& what,
                                 std::vector<std::string>& todos, PyTranslation& t);

    void writeDaughterElement(std::size_t oi, const MgElement& e, bool isNode, const RuleScope& scope,
                              std::vector<std::string>& lines);

    static bool isOrdered(const MgProduction& p);

    void writeRule(const MgProduction& p, RuleScope& scope);
};

}  // namespace g2d::import::detail
