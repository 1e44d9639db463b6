#pragma once
// Evaluates IR expressions at run time, on the runtime's values and graph.
#include <optional>
#include <stdexcept>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/rng.hpp"
#include "g2d/value.hpp"
#include "g2d/drawing_cost.hpp"
#include "ir/ir.hpp"

namespace g2d::interp {

// A run-time error in the grammar (division by zero, NaN, out of range...).
class EvalError : public std::runtime_error {
public:
    EvalError(Span span, const std::string& message) : std::runtime_error(message), span(span) {}
    Span span;
};

struct EvalFrame {
    const ir::Program* prog = nullptr;
    const std::vector<rt::Value>* params = nullptr;
    const std::vector<rt::Value>* consts = nullptr;
    std::vector<rt::Value>* locals = nullptr;
    const std::vector<rt::Value>* fnArgs = nullptr;
    const rt::Graph* graph = nullptr;
    const rt::NodeId* nodes = nullptr;  // the match's host nodes, by pattern index
    const rt::EdgeId* edges = nullptr;
    const rt::FaceId* faces = nullptr;
    rt::Rng* rng = nullptr;
    const std::vector<std::optional<rt::Value>>* placed = nullptr;  // automatic positions, by daughter node
    ir::ElemClass selfClass = ir::ElemClass::Node;    // kind style expressions
    std::uint32_t self = rt::kNoId;
    const rt::KindCounts* counts = nullptr;           // `layout angles`' cost
};

rt::Value evaluate(const ir::Expr& e, EvalFrame& f);
bool evaluateBool(const ir::Expr& e, EvalFrame& f);

rt::Value fromLiteral(const ir::Value& v);
// How a value prints in str() and format(): enums by their value's name.
std::string display(const rt::Value& v, const ir::Program& prog);

}  // namespace g2d::interp
