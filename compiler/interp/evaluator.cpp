#include "interp/evaluator.hpp"

#include "g2d/deadline.hpp"

#include <charconv>
#include <climits>
#include <cmath>

#include "g2d/ops.hpp"
#include "g2d/vec_math.hpp"

namespace g2d::interp {

using ir::Builtin;
using ir::ExprOp;
using rt::Value;
using rt::vec2;

rt::Value fromLiteral(const ir::Value& v) {
    return std::visit(
        [](const auto& x) -> Value {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, ir::Vec2>) return vec2{x.x, x.y};
            else if constexpr (std::is_same_v<T, ir::EnumValue>) return rt::EnumVal{x.enumId, x.index};
            else return x;
        },
        v);
}

std::string display(const Value& v, const ir::Program& prog) {
    if (auto* e = std::get_if<rt::EnumVal>(&v)) return prog.enums[e->enumId].values[e->index];
    return rt::toString(v);
}

namespace {

long long I(const Value& v) { return std::get<long long>(v); }
double F(const Value& v) { return std::get<double>(v); }
bool B(const Value& v) { return std::get<bool>(v); }
vec2 V(const Value& v) { return std::get<vec2>(v); }
const std::string& S(const Value& v) { return std::get<std::string>(v); }

rt::FormatHole hole(const Value& v, const ir::Program& prog) {
    rt::FormatHole h;
    h.text = display(v, prog);
    if (auto* d = std::get_if<double>(&v)) { h.kind = 1; h.number = *d; }
    else if (auto* n = std::get_if<long long>(&v)) { h.kind = 1; h.number = static_cast<double>(*n); }
    else if (auto* p = std::get_if<vec2>(&v)) { h.kind = 2; h.number = p->x; h.number2 = p->y; }
    return h;
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
    case Builtin::Choice: return a[static_cast<std::size_t>(f.rng->below(a.size()))];
    default: return rt::callBuiltin(e.builtin, a.data(), a.size(), f.rng);
    }
}

Value arith(const ir::Expr& e, const Value& l, const Value& r) {
    const auto lk = e.args[0].type.kind, rk = e.args[1].type.kind;
    using K = ir::TypeKind;
    if (lk == K::Int && rk == K::Int) {
        const long long a = I(l), b = I(r);
        switch (e.op) {
        case ExprOp::Add: return rt::addInt(a, b);
        case ExprOp::Sub: return rt::subInt(a, b);
        case ExprOp::Mul: return rt::mulInt(a, b);
        case ExprOp::Mod: return rt::modInt(a, b);
        case ExprOp::Lt: return a < b;
        case ExprOp::Le: return a <= b;
        case ExprOp::Gt: return a > b;
        case ExprOp::Ge: return a >= b;
        default: break;
        }
    } else if (lk == K::Float && rk == K::Float) {
        const double a = F(l), b = F(r);
        switch (e.op) {
        case ExprOp::Add: return rt::finite(a + b);
        case ExprOp::Sub: return rt::finite(a - b);
        case ExprOp::Mul: return rt::finite(a * b);
        case ExprOp::Div: return rt::divFloat(a, b);
        case ExprOp::Mod: return rt::modFloat(a, b);
        case ExprOp::Lt: return a < b;
        case ExprOp::Le: return a <= b;
        case ExprOp::Gt: return a > b;
        case ExprOp::Ge: return a >= b;
        default: break;
        }
    } else if (lk == K::Vec2 && rk == K::Vec2) {
        if (e.op == ExprOp::Add) return rt::finite(V(l) + V(r));
        if (e.op == ExprOp::Sub) return rt::finite(V(l) - V(r));
    } else if (lk == K::Vec2 && rk == K::Float) {
        if (e.op == ExprOp::Mul) return rt::finite(V(l) * F(r));
        if (e.op == ExprOp::Div) return rt::divVec(V(l), F(r));
    } else if (lk == K::Float && rk == K::Vec2 && e.op == ExprOp::Mul) {
        return rt::finite(F(l) * V(r));
    }
    if (e.op == ExprOp::Add) return S(l) + S(r);
    if (e.op == ExprOp::Eq) return l == r;
    if (e.op == ExprOp::Ne) return l != r;
    throw rt::OpError("unsupported operation");
}

Value fact(const ir::Expr& e, EvalFrame& f, ir::ElemClass cls, std::uint32_t id) {
    const rt::Graph& g = *f.graph;
    if (cls == ir::ElemClass::Edge) {
        if (e.fact == ir::ElemFact::Age) return g.edgeAge(id);
        return static_cast<long long>(id);
    }
    switch (e.fact) {
    case ir::ElemFact::Pos: return g.pos(id);
    case ir::ElemFact::Age: return g.nodeAge(id);
    case ir::ElemFact::Id: return static_cast<long long>(id);
    case ir::ElemFact::Degree: return static_cast<long long>(g.degree(id));
    case ir::ElemFact::InDegree: return static_cast<long long>(g.inDegree(id));
    case ir::ElemFact::OutDegree: return static_cast<long long>(g.outDegree(id));
    }
    return 0LL;
}

Value evaluateUnchecked(const ir::Expr& e, EvalFrame& f);

Value evaluateUnchecked(const ir::Expr& e, EvalFrame& f) {
    switch (e.op) {
    case ExprOp::Literal: return fromLiteral(e.value);
    case ExprOp::Param: return (*f.params)[e.index];
    case ExprOp::Const: return (*f.consts)[e.index];
    case ExprOp::Local: return (*f.locals)[e.index];
    case ExprOp::FnArg: return (*f.fnArgs)[e.index];
    case ExprOp::Attr:
        if (e.elem.cls == ir::ElemClass::Edge) return f.graph->edgeAttr(f.edges[e.elem.index], e.index);
        return f.graph->nodeAttr(f.nodes[e.elem.index], e.index);
    case ExprOp::SelfAttr:
        return f.selfClass == ir::ElemClass::Edge ? f.graph->edgeAttr(f.self, e.index) : f.graph->nodeAttr(f.self, e.index);
    case ExprOp::Fact: {
        const ir::ElemClass cls = e.elem.cls;
        return fact(e, f, cls, cls == ir::ElemClass::Edge ? f.edges[e.elem.index] : f.nodes[e.elem.index]);
    }
    case ExprOp::SelfFact: return fact(e, f, f.selfClass, f.self);
    case ExprOp::Placed: return *(*f.placed)[e.index];
    case ExprOp::VecX: return V(evaluate(e.args[0], f)).x;
    case ExprOp::VecY: return V(evaluate(e.args[0], f)).y;
    case ExprOp::Neg: {
        Value v = evaluate(e.args[0], f);
        if (auto* i = std::get_if<long long>(&v)) return rt::negInt(*i);
        if (auto* d = std::get_if<double>(&v)) return -*d;
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
    default: {
        Value l = evaluate(e.args[0], f);
        Value r = evaluate(e.args[1], f);
        return arith(e, l, r);
    }
    }
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
rt::vec2 evaluateVec(const ir::Expr& e, EvalFrame& f) { return V(evaluate(e, f)); }

}  // namespace g2d::interp
