#include "interp/evaluator.hpp"

#include "g2d/deadline.hpp"

#include <charconv>
#include <stdexcept>
#include <climits>
#include <cmath>

#include "g2d/ops.hpp"
#include "g2d/vec_math.hpp"

namespace g2d::interp {

using ir::Builtin;
using ir::ExprOp;
using rt::Value;
using rt::vec2;

rt::Value fromLiteral(const ir::Value& v) { return ir::toRuntime(v); }

std::string display(const Value& v, const ir::Program& prog) {
    if (auto* e = std::get_if<rt::EnumVal>(&v)) return prog.enums[e->enumId].values[e->index];
    return rt::toString(v);
}

namespace {

bool B(const Value& v) { return std::get<bool>(v); }
vec2 V(const Value& v) { return std::get<vec2>(v); }
const std::string& S(const Value& v) { return std::get<std::string>(v); }

rt::FormatHole hole(const Value& v, const ir::Program& prog) {
    if (std::holds_alternative<rt::EnumVal>(v)) return rt::FormatHole{display(v, prog)};
    return rt::formatHole(v);
}

// Built-in calls; rt::OpError from the runtime's checked operations is turned
// into an EvalError at the call by evaluate().
Value call(const ir::Expr& e, EvalFrame& f) {
    // Arguments are evaluated left to right (random draws happen in that order).
    std::vector<Value> a;
    a.reserve(e.args.size());
    for (const auto& arg : e.args) a.push_back(evaluate(arg, f));
    switch (e.builtin) {
    case Builtin::ToStr: return display(a[0], *f.prog);
    case Builtin::Format: {
        std::vector<rt::FormatHole> holes;
        for (std::size_t i = 1; i < a.size(); ++i) holes.push_back(hole(a[i], *f.prog));
        return rt::formatTemplate(S(a[0]), holes.data(), holes.size());
    }
    case Builtin::Choice: return a[rt::fn::choiceIndex(*f.rng, a.size())];
    default: return rt::callBuiltin(e.builtin, a.data(), a.size(), f.rng);
    }
}


// The host element bound to a pattern element.
std::uint32_t matchElement(const EvalFrame& f, const ir::ElemRef& r) {
    return r.cls == ir::ElemClass::Edge ? f.edges[r.index] : r.cls == ir::ElemClass::Face ? f.faces[r.index] : f.nodes[r.index];
}

Value fact(const ir::Expr& e, EvalFrame& f, ir::ElemClass cls, std::uint32_t id) {
    return rt::elementFact(*f.graph, cls, id, e.fact);
}

Value evaluateUnchecked(const ir::Expr& e, EvalFrame& f);

Value evaluateUnchecked(const ir::Expr& e, EvalFrame& f) {
    switch (e.op) {
    case ExprOp::Literal: return fromLiteral(e.value);
    case ExprOp::Param: return (*f.params)[e.index];
    case ExprOp::Const: return (*f.consts)[e.index];
    case ExprOp::Local: return (*f.locals)[e.index];
    case ExprOp::FnArg: return (*f.fnArgs)[e.index];
    case ExprOp::Attr: return f.graph->attrOf(e.elem.cls, matchElement(f, e.elem), e.index);
    case ExprOp::SelfAttr: return f.graph->attrOf(f.selfClass, f.self, e.index);
    case ExprOp::Fact: {
        const ir::ElemClass cls = e.elem.cls;
        return fact(e, f, cls, matchElement(f, e.elem));
    }
    case ExprOp::SelfFact: return fact(e, f, f.selfClass, f.self);
    case ExprOp::Placed: return *(*f.placed)[e.index];
    case ExprOp::CompoundValue: return rt::compoundValue(*f.graph, e.index, e.slot);
    case ExprOp::Count: return (*f.counts)[e.index];
    case ExprOp::VecX:
    case ExprOp::VecY:
    case ExprOp::VecZ: {
        const Value v = evaluate(e.args[0], f);
        const int axis = e.op == ExprOp::VecX ? 0 : e.op == ExprOp::VecY ? 1 : 2;
        if (const auto* p = std::get_if<rt::vec3>(&v)) return (*p)[axis];
        return V(v)[axis];
    }
    case ExprOp::Neg: {
        Value v = evaluate(e.args[0], f);
        if (auto* i = std::get_if<long long>(&v)) return rt::negInt(*i);
        if (auto* d = std::get_if<double>(&v)) return -*d;
        if (auto* p = std::get_if<rt::vec3>(&v)) return -*p;
        return -V(v);
    }
    case ExprOp::Not: return !B(evaluate(e.args[0], f));
    case ExprOp::And: return B(evaluate(e.args[0], f)) && B(evaluate(e.args[1], f));
    case ExprOp::Or: return B(evaluate(e.args[0], f)) || B(evaluate(e.args[1], f));
    case ExprOp::Cond: return B(evaluate(e.args[0], f)) ? evaluate(e.args[1], f) : evaluate(e.args[2], f);
    case ExprOp::Call: return call(e, f);
    case ExprOp::CallFn: {
        rt::checkDeadline();   // a chain of calls can take 2^n: --timeout must see it
        std::vector<Value> args;
        args.reserve(e.args.size());
        for (const auto& a : e.args) args.push_back(evaluate(a, f));
        EvalFrame inner = f;
        inner.fnArgs = &args;
        return evaluate(f.prog->functions[e.index].body, inner);
    }
    case ExprOp::Add:
    case ExprOp::Sub:
    case ExprOp::Mul:
    case ExprOp::Div:
    case ExprOp::Mod:
    case ExprOp::Lt:
    case ExprOp::Le:
    case ExprOp::Gt:
    case ExprOp::Ge:
    case ExprOp::Eq:
    case ExprOp::Ne: {
        Value l = evaluate(e.args[0], f);
        Value r = evaluate(e.args[1], f);
        return rt::binaryOp(*ir::binaryOperator(e.op), l, r);
    }
    }
    throw std::logic_error("an expression operation out of range");
}

}  // namespace

Value evaluate(const ir::Expr& e, EvalFrame& f) {
    try {
        return evaluateUnchecked(e, f);
    } catch (const rt::OpError& err) {
        // The innermost expression that failed names the place.
        throw EvalError(e.span, err.what());
    }
}

bool evaluateBool(const ir::Expr& e, EvalFrame& f) { return B(evaluate(e, f)); }

}  // namespace g2d::interp
