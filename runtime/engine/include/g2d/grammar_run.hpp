#pragma once
// One run of a grammar, as a back end provides it. The interpreter implements
// it by walking the IR; a compiled grammar by generated code. The driver
// (run_driver.hpp) does everything else the same way for both: parameters,
// outputs, the derivation, statistics and error messages.
//
// It declares the store, the rules and the drawing's items without
// including them: embedding programs hold a GrammarRun (grammar.hpp) but
// need none of those headers; back ends include what they implement.
#include <cstdint>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "g2d/elem_class.hpp"
#include "g2d/json_schema.hpp"
#include "g2d/param_parse.hpp"
#include "g2d/view_box.hpp"

namespace g2d::rt {

class Graph;      // graph.hpp
class RuleSet;    // derivation.hpp
class Rng;        // rng.hpp
struct DrawItem;  // svg_writer.hpp

struct ParamSpec {
    std::string name;
    std::string typeName;                 // for messages: int, float, vec2, an enum's name
    ParamType type = ParamType::Int;
    int enumId = -1;
    std::vector<std::string> enumValues;
    Value defaultValue;
    // The declaration's `in MIN..MAX [step STEP]` (int and float only): the
    // values a run accepts, inclusive; `step` only when written (sliders take
    // 1 for an int without one).
    std::optional<double> min, max, step;
};

// `text` as a value of `p` (parseParamValue's forms) within its range, or
// nothing with `why` set in words that name the parameter: `-D`, the studio
// and Grammar::set read values through it, so all refuse alike.
std::optional<Value> parameterValue(const ParamSpec& p, const std::string& text, std::string& why);

// Where a run-time error happened in the grammar's source.
struct SourceLocation {
    std::string file;
    unsigned line = 0, col = 0, endCol = 0;
    std::string lineText;
};

class GrammarRun {
public:
    virtual ~GrammarRun() = default;

    virtual const std::vector<ParamSpec>& params() const = 0;
    // Evaluates the constants and the kinds' defaults and builds the axiom.
    virtual void start(const std::vector<Value>& params, Rng& rng) = 0;
    // The grammar's global limit (nullopt: it sets none), per-priority and per-rule limits.
    virtual std::optional<long long> stepLimit() = 0;
    virtual std::map<long long, long long> priorityLimits() = 0;
    virtual std::map<std::size_t, long long> ruleLimits() = 0;
    // The counts of the command lists' `repeat N { … }` (SequenceEntry::index), checked (checkedRepeatCount).
    virtual std::vector<long long> repeatCounts() = 0;
    // The grammar's `canvas` (nullopt: it sets none), evaluated after start()
    // and checked (checkedCanvas: a bad one throws, located).
    virtual std::optional<ViewBox> canvas() = 0;
    virtual Graph& graph() = 0;
    virtual RuleSet& rules() = 0;

    // The item of one live element (outputs make them one at a time).
    virtual void drawItem(ElemClass cls, std::uint32_t id, DrawItem& out) = 0;
    // Every live element's item at once (the small pages: trace, view).
    std::vector<DrawItem> drawItems();
    virtual const std::vector<std::string>& svgDefs() const = 0;
    virtual const JsonSchema& jsonSchema() const = 0;
    virtual Value attribute(ElemClass cls, std::uint32_t id, int attr) const = 0;

    // For a failure thrown by start() or the rules: where in the source, if
    // known, and the rule being applied ("" outside rules).
    virtual std::optional<SourceLocation> locate(const std::exception& e) const = 0;
    virtual std::string currentRule() const = 0;
};

}  // namespace g2d::rt
