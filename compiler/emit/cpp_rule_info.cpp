#include "emit/cpp_rule_info.hpp"

#include "emit/cpp_expr.hpp"

namespace g2d::emit {

namespace {

// One C++ literal per field type of RuleInfo; a field of a new type fails to
// compile here until it has one.
std::string literal(const std::string& s) { return cppString(s); }
std::string literal(long long i) { return cppLiteral(ir::Value{i}, ir::kIntType); }
std::string literal(int i) { return std::to_string(i); }
std::string literal(std::uint8_t b) { return std::to_string(static_cast<int>(b)); }
std::string literal(double x) { return cppLiteral(ir::Value{x}, ir::kFloatType); }
std::string literal(bool b) { return b ? "true" : "false"; }

std::string literal(rt::Pick p) {
    switch (p) {
    case rt::Pick::Random: return "Pick::Random";
    case rt::Pick::Oldest: return "Pick::Oldest";
    case rt::Pick::OldestGeneration: return "Pick::OldestGeneration";
    }
    return "Pick::Random";
}

std::string literal(rt::Incidence r) {
    switch (r) {
    case rt::Incidence::None: return "Incidence::None";
    case rt::Incidence::PatternEdges: return "Incidence::PatternEdges";
    case rt::Incidence::AllEdges: return "Incidence::AllEdges";
    }
    return "Incidence::AllEdges";
}

std::string literal(const rt::DaughterShape::NewEdge& e) {
    return "{" + literal(e.src) + ", " + literal(e.dst) + ", " + literal(e.kind) + "}";
}

std::string typeName(int) { return "int"; }
std::string typeName(long long) { return "long long"; }
std::string typeName(std::uint8_t) { return "std::uint8_t"; }
std::string typeName(double) { return "double"; }
std::string typeName(rt::Incidence) { return "Incidence"; }
std::string typeName(const rt::DaughterShape&) { return "DaughterShape"; }
std::string typeName(const rt::DaughterShape::NewEdge&) { return "DaughterShape::NewEdge"; }
template <class T>
std::string typeName(const std::vector<T>&) {
    return "std::vector<" + typeName(T{}) + ">";
}

template <class T>
std::string literal(const std::vector<T>& v);

std::string literal(const rt::DaughterShape& s) {
    return "DaughterShape{" + literal(s.deletedNodes) + ", " + literal(s.deletedEdges) + ", " + literal(s.newNodes) + ", " +
           literal(s.newEdges) + ", " + literal(s.newNodeKinds) + "}";
}

// Typed, so that an empty list and a nested one keep their element type.
template <class T>
std::string literal(const std::vector<T>& v) {
    std::string out = "std::vector<" + typeName(T{}) + ">{";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + literal(v[i]);
    return out + "}";
}

}  // namespace

std::string ruleInfoText(const rt::RuleInfo& info, const std::string& in) {
    std::string out = in + "RuleInfo info;\n";
    rt::eachRuleInfoField(info, [&](const char* name, const auto& field) {
        out += in + "info." + name + " = " + literal(field) + ";\n";
    });
    return out;
}

}  // namespace g2d::emit
