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
    const bool isInt = e.type.kind == ir::TypeKind::Int;
    using rt::finite;
    switch (e.builtin) {
    case Builtin::Sin: return finite(std::sin(F(a[0])));
    case Builtin::Cos: return finite(std::cos(F(a[0])));
    case Builtin::Tan: return finite(std::tan(F(a[0])));
    case Builtin::Asin: return finite(std::asin(F(a[0])));
    case Builtin::Acos: return finite(std::acos(F(a[0])));
    case Builtin::Atan: return finite(std::atan(F(a[0])));
    case Builtin::Atan2: return finite(std::atan2(F(a[0]), F(a[1])));
    case Builtin::Sqrt: return finite(std::sqrt(F(a[0])));
    case Builtin::Exp: return finite(std::exp(F(a[0])));
    case Builtin::Log: return finite(std::log(F(a[0])));
    case Builtin::Pow: return finite(std::pow(F(a[0]), F(a[1])));
    case Builtin::Hypot: return finite(std::hypot(F(a[0]), F(a[1])));
    case Builtin::Floor: return rt::floorToInt(F(a[0]));
    case Builtin::Ceil: return rt::ceilToInt(F(a[0]));
    case Builtin::Round: return rt::roundToInt(F(a[0]));
    case Builtin::Radians: return finite(F(a[0]) * 3.141592653589793 / 180.0);
    case Builtin::Degrees: return finite(F(a[0]) * 180.0 / 3.141592653589793);
    case Builtin::Abs: return isInt ? Value{rt::absInt(I(a[0]))} : Value{std::fabs(F(a[0]))};
    case Builtin::Sign:
        if (isInt) return static_cast<long long>((I(a[0]) > 0) - (I(a[0]) < 0));
        return static_cast<double>((F(a[0]) > 0) - (F(a[0]) < 0));
    case Builtin::Clamp:
        if (isInt) return std::min(std::max(I(a[0]), I(a[1])), I(a[2]));
        return std::min(std::max(F(a[0]), F(a[1])), F(a[2]));
    case Builtin::Min:
    case Builtin::Max: {
        Value best = a[0];
        for (std::size_t i = 1; i < a.size(); ++i) {
            const bool less = isInt ? I(a[i]) < I(best) : F(a[i]) < F(best);
            const bool greater = isInt ? I(a[i]) > I(best) : F(a[i]) > F(best);
            if (e.builtin == Builtin::Min ? less : greater) best = a[i];
        }
        return best;
    }
    case Builtin::MakeVec2: return vec2{F(a[0]), F(a[1])};
    case Builtin::Dot: return finite(rt::dot(V(a[0]), V(a[1])));
    case Builtin::Cross: return finite(rt::cross(V(a[0]), V(a[1])));
    case Builtin::Length: return finite(rt::length(V(a[0])));
    case Builtin::Distance: return finite(rt::distance(V(a[0]), V(a[1])));
    case Builtin::Normalize: return rt::normalize(V(a[0]));
    case Builtin::PerpLeft: return rt::perpLeft(V(a[0]));
    case Builtin::PerpRight: return rt::perpRight(V(a[0]));
    case Builtin::Rotate: return finite(rt::rotate(V(a[0]), F(a[1])));
    case Builtin::RotateAround: return finite(rt::rotateAround(V(a[0]), F(a[1]), V(a[2])));
    case Builtin::Angle: return rt::angle(V(a[0]));
    case Builtin::AngleBetween: return rt::angleBetween(V(a[0]), V(a[1]));
    case Builtin::Lerp:
        if (e.type.kind == ir::TypeKind::Vec2) return finite(rt::lerp(V(a[0]), V(a[1]), F(a[2])));
        return finite(rt::lerp(F(a[0]), F(a[1]), F(a[2])));
    case Builtin::ToInt:
        if (auto* d = std::get_if<double>(&a[0])) return rt::floatToInt(*d);
        if (auto* b = std::get_if<bool>(&a[0])) return static_cast<long long>(*b);
        if (auto* s = std::get_if<std::string>(&a[0])) return rt::parseInt(*s);
        return a[0];
    case Builtin::ToFloat:
        if (auto* n = std::get_if<long long>(&a[0])) return static_cast<double>(*n);
        if (auto* b = std::get_if<bool>(&a[0])) return *b ? 1.0 : 0.0;
        if (auto* s = std::get_if<std::string>(&a[0])) return rt::parseFloat(*s);
        return a[0];
    case Builtin::ToStr: return display(a[0], *f.prog);
    case Builtin::Format: {
        std::vector<rt::FormatHole> holes;
        for (std::size_t i = 1; i < a.size(); ++i) holes.push_back(hole(a[i], *f.prog));
        return rt::formatTemplate(S(a[0]), holes.data(), holes.size());
    }
    case Builtin::Random: return f.rng->unit();
    case Builtin::Uniform: return f.rng->uniform(F(a[0]), F(a[1]));
    case Builtin::RandInt:
        if (I(a[0]) > I(a[1]))
            throw rt::OpError("randint(" + std::to_string(I(a[0])) + ", " + std::to_string(I(a[1])) + "): empty range");
        return f.rng->range(I(a[0]), I(a[1]));
    case Builtin::Choice: return a[static_cast<std::size_t>(f.rng->below(a.size()))];
    case Builtin::Normal: return f.rng->normal(F(a[0]), F(a[1]));
    }
    throw rt::OpError("unknown built-in");
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

Value fact(const ir::Expr& e, EvalFrame& f, bool isEdge, std::uint32_t id) {
    const rt::Graph& g = *f.graph;
    if (isEdge) {
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
        return f.selfIsEdge ? f.graph->edgeAttr(f.self, e.index) : f.graph->nodeAttr(f.self, e.index);
    case ExprOp::Fact: {
        const bool isEdge = e.elem.cls == ir::ElemClass::Edge;
        return fact(e, f, isEdge, isEdge ? f.edges[e.elem.index] : f.nodes[e.elem.index]);
    }
    case ExprOp::SelfFact: return fact(e, f, f.selfIsEdge, f.self);
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
