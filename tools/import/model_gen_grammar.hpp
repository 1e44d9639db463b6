#pragma once
// The original tool's YAML grammar (model_gen), as plain data: what the file
// says, with its lines for messages. Ids are kept as the file's text.

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace g2d::import {

struct MgScalar {
    enum class Kind { String, Int, Float, Bool, Null };
    std::string text;       // as written (for a Bool: "True"/"False")
    Kind kind = Kind::String;
    bool quoted = false;    // a quoted YAML string: never a number, even '0'
};

struct MgAttribute {
    std::string key;
    MgScalar value;
    int line = 0;           // 1-based
};

struct MgElement {
    std::string id;
    std::vector<MgAttribute> attributes;
    std::optional<std::string> vertex1, vertex2;   // edges; nullopt: a dangling end
    int line = 0;

    const MgAttribute* attribute(std::string_view key) const {
        for (const auto& a : attributes) if (a.key == key) return &a;
        return nullptr;
    }
};

struct MgGraph {
    std::string id;
    std::vector<MgElement> vertices;
    std::vector<MgElement> edges;
    int line = 0;
};

struct MgRequirement {        // a name bound to a mother element in daughter expressions
    std::string name;
    std::string motherId;
};

struct MgVarCalc {
    std::string name;
    std::string expression;
    std::string when;         // "application" or "run"
    int line = 0;
};

struct MgOption {
    std::string id;
    double weight = 1;
    MgGraph daughter;
    std::vector<std::pair<std::string, std::string>> mapping;   // mother id → daughter id
    // For one daughter element (by id), or "all".
    std::vector<std::pair<std::string, std::vector<MgRequirement>>> requirements;
    std::vector<std::pair<std::string, MgScalar>> conditions;
    std::vector<MgVarCalc> varCalc;
    int line = 0;
};

struct MgVector {             // `A: id` (a point) or `v1: [id1, id2]` (from id1 to id2)
    std::string name;
    std::string from;         // the point, or the start
    std::optional<std::string> to;
    int line = 0;
};

struct MgProduction {
    std::string name;
    int priority = 0;
    std::vector<std::pair<std::string, MgScalar>> conditions;
    std::vector<MgVector> vectors;
    MgGraph mother;
    std::vector<MgOption> options;
    int line = 0;
};

struct MgGlobal {
    std::string name;
    std::string expression;
    int line = 0;
};

struct MgGrammar {
    std::vector<std::pair<std::string, MgGraph>> hosts;
    std::vector<MgProduction> productions;
    std::vector<MgGlobal> globals;
    std::vector<std::pair<std::string, long long>> maxDerivations;   // "all" or a priority
    int maxDerivationsLine = 0;
    std::vector<std::pair<std::string, std::string>> svgFilters;      // id → <filter> element
};

// A file that is not a grammar of the tool: the line (1-based) and what is wrong.
struct MgError : std::runtime_error {
    int line;
    MgError(int line_, const std::string& message) : std::runtime_error(message), line(line_) {}
};

MgGrammar readModelGenGrammar(const std::string& yamlText);

// Python's truth of a flag as the files write it (true, 'True', 1).
inline bool isTrue(const MgScalar& s) { return s.text == "True" || s.text == "true" || s.text == "1"; }

// The label a mother condition asks for (`attr=='Branch'`), if it is that simple.
std::optional<std::string> labelTested(const std::string& condition);

}  // namespace g2d::import
