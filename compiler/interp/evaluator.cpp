#include "interp/evaluator.hpp"

#include <charconv>
#include <climits>
#include <cmath>

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

[[noreturn]] void fail(const ir::Expr& e, const std::string& message) { throw EvalError(e.span, message); }

double finite(const ir::Expr& e, double x) {
    if (!std::isfinite(x)) fail(e, std::isnan(x) ? "the result is not a number (NaN)" : "the result is infinite");
    return x;
}

vec2 finite(const ir::Expr& e, vec2 v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) fail(e, "the result is not a finite vector");
    return v;
}

long long toInt(const ir::Expr& e, double x) {
    if (!std::isfinite(x) || x >= 9.2233720368547758e18 || x < -9.2233720368547758e18)
        fail(e, "cannot convert " + rt::formatNumber(x) + " to int: out of range");
    return static_cast<long long>(x);
}

std::string formatTemplate(const ir::Expr& e, const std::vector<Value>& args, const ir::Program& prog) {
    const std::string& t = S(args[0]);
    std::string out;
    std::size_t next = 1;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if ((t[i] == '{' || t[i] == '}') && i + 1 < t.size() && t[i + 1] == t[i]) { out += t[i++]; continue; }
        if (t[i] != '{') { out += t[i]; continue; }
        const std::size_t close = t.find('}', i);
        const std::string spec = t.substr(i + 1, close - i - 1);
        const Value& v = args.at(next++);
        if (spec.empty()) {
            out += display(v, prog);
        } else {
            const int decimals = std::stoi(spec.substr(2));
            if (auto* d = std::get_if<double>(&v)) out += rt::formatFixed(*d, decimals);
            else if (auto* n = std::get_if<long long>(&v)) out += rt::formatFixed(static_cast<double>(*n), decimals);
            else if (auto* p = std::get_if<vec2>(&v))
                out += rt::formatFixed(p->x, decimals) + " " + rt::formatFixed(p->y, decimals);
            else out += display(v, prog);
        }
        i = close;
    }
    (void)e;
    return out;
}

Value call(const ir::Expr& e, EvalFrame& f) {
    // Arguments are evaluated left to right (random draws happen in that order).
    std::vector<Value> a;
    a.reserve(e.args.size());
    for (const auto& arg : e.args) a.push_back(evaluate(arg, f));
    const bool isInt = e.type.kind == ir::TypeKind::Int;
    switch (e.builtin) {
    case Builtin::Sin: return finite(e, std::sin(F(a[0])));
    case Builtin::Cos: return finite(e, std::cos(F(a[0])));
    case Builtin::Tan: return finite(e, std::tan(F(a[0])));
    case Builtin::Asin: return finite(e, std::asin(F(a[0])));
    case Builtin::Acos: return finite(e, std::acos(F(a[0])));
    case Builtin::Atan: return finite(e, std::atan(F(a[0])));
    case Builtin::Atan2: return finite(e, std::atan2(F(a[0]), F(a[1])));
    case Builtin::Sqrt: return finite(e, std::sqrt(F(a[0])));
    case Builtin::Exp: return finite(e, std::exp(F(a[0])));
    case Builtin::Log: return finite(e, std::log(F(a[0])));
    case Builtin::Pow: return finite(e, std::pow(F(a[0]), F(a[1])));
    case Builtin::Hypot: return finite(e, std::hypot(F(a[0]), F(a[1])));
    case Builtin::Floor: return toInt(e, std::floor(F(a[0])));
    case Builtin::Ceil: return toInt(e, std::ceil(F(a[0])));
    case Builtin::Round: return toInt(e, rt::roundHalfAway(F(a[0])));
    case Builtin::Radians: return F(a[0]) * 3.141592653589793 / 180.0;
    case Builtin::Degrees: return F(a[0]) * 180.0 / 3.141592653589793;
    case Builtin::Abs:
        if (isInt) {
            if (I(a[0]) == LLONG_MIN) fail(e, "integer overflow");
            return std::llabs(I(a[0]));
        }
        return std::fabs(F(a[0]));
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
    case Builtin::Dot: return finite(e, rt::dot(V(a[0]), V(a[1])));
    case Builtin::Cross: return finite(e, rt::cross(V(a[0]), V(a[1])));
    case Builtin::Length: return finite(e, rt::length(V(a[0])));
    case Builtin::Distance: return finite(e, rt::distance(V(a[0]), V(a[1])));
    case Builtin::Normalize: return rt::normalize(V(a[0]));
    case Builtin::PerpLeft: return rt::perpLeft(V(a[0]));
    case Builtin::PerpRight: return rt::perpRight(V(a[0]));
    case Builtin::Rotate: return finite(e, rt::rotate(V(a[0]), F(a[1])));
    case Builtin::RotateAround: return finite(e, rt::rotateAround(V(a[0]), F(a[1]), V(a[2])));
    case Builtin::Angle: return rt::angle(V(a[0]));
    case Builtin::AngleBetween: return rt::angleBetween(V(a[0]), V(a[1]));
    case Builtin::Lerp:
        if (e.type.kind == ir::TypeKind::Vec2) return finite(e, rt::lerp(V(a[0]), V(a[1]), F(a[2])));
        return finite(e, rt::lerp(F(a[0]), F(a[1]), F(a[2])));
    case Builtin::ToInt:
        if (auto* d = std::get_if<double>(&a[0])) return toInt(e, *d);
        if (auto* b = std::get_if<bool>(&a[0])) return static_cast<long long>(*b);
        if (auto* s = std::get_if<std::string>(&a[0])) {
            long long v = 0;
            auto res = std::from_chars(s->data(), s->data() + s->size(), v);
            if (res.ec != std::errc() || res.ptr != s->data() + s->size()) fail(e, "int(\"" + *s + "\"): not an integer");
            return v;
        }
        return a[0];
    case Builtin::ToFloat:
        if (auto* n = std::get_if<long long>(&a[0])) return static_cast<double>(*n);
        if (auto* b = std::get_if<bool>(&a[0])) return *b ? 1.0 : 0.0;
        if (auto* s = std::get_if<std::string>(&a[0])) {
            double v = 0;
            auto res = std::from_chars(s->data(), s->data() + s->size(), v);
            if (res.ec != std::errc() || res.ptr != s->data() + s->size() || !std::isfinite(v))
                fail(e, "float(\"" + *s + "\"): not a number");
            return v;
        }
        return a[0];
    case Builtin::ToStr: return display(a[0], *f.prog);
    case Builtin::Format: return formatTemplate(e, a, *f.prog);
    case Builtin::Random: return f.rng->unit();
    case Builtin::Uniform: return f.rng->uniform(F(a[0]), F(a[1]));
    case Builtin::RandInt:
        if (I(a[0]) > I(a[1]))
            fail(e, "randint(" + std::to_string(I(a[0])) + ", " + std::to_string(I(a[1])) + "): empty range");
        return f.rng->range(I(a[0]), I(a[1]));
    case Builtin::Choice: return a[static_cast<std::size_t>(f.rng->below(a.size()))];
    case Builtin::Normal: return f.rng->normal(F(a[0]), F(a[1]));
    }
    fail(e, "unknown built-in");
}

Value arith(const ir::Expr& e, const Value& l, const Value& r) {
    const auto lk = e.args[0].type.kind, rk = e.args[1].type.kind;
    using K = ir::TypeKind;
    if (lk == K::Int && rk == K::Int) {
        long long a = I(l), b = I(r), out = 0;
        switch (e.op) {
        case ExprOp::Add: if (__builtin_add_overflow(a, b, &out)) fail(e, "integer overflow"); return out;
        case ExprOp::Sub: if (__builtin_sub_overflow(a, b, &out)) fail(e, "integer overflow"); return out;
        case ExprOp::Mul: if (__builtin_mul_overflow(a, b, &out)) fail(e, "integer overflow"); return out;
        case ExprOp::Mod:
            if (b == 0) fail(e, "division by zero");
            if (a == LLONG_MIN && b == -1) fail(e, "integer overflow");
            return rt::imodFloor(a, b);
        case ExprOp::Lt: return a < b;
        case ExprOp::Le: return a <= b;
        case ExprOp::Gt: return a > b;
        case ExprOp::Ge: return a >= b;
        case ExprOp::Eq: return a == b;
        case ExprOp::Ne: return a != b;
        default: break;
        }
    } else if (lk == K::Float && rk == K::Float) {
        double a = F(l), b = F(r);
        switch (e.op) {
        case ExprOp::Add: return finite(e, a + b);
        case ExprOp::Sub: return finite(e, a - b);
        case ExprOp::Mul: return finite(e, a * b);
        case ExprOp::Div: if (b == 0) fail(e, "division by zero"); return finite(e, a / b);
        case ExprOp::Mod: if (b == 0) fail(e, "division by zero"); return finite(e, rt::fmodFloor(a, b));
        case ExprOp::Lt: return a < b;
        case ExprOp::Le: return a <= b;
        case ExprOp::Gt: return a > b;
        case ExprOp::Ge: return a >= b;
        case ExprOp::Eq: return a == b;
        case ExprOp::Ne: return a != b;
        default: break;
        }
    } else if (lk == K::Vec2 && rk == K::Vec2) {
        switch (e.op) {
        case ExprOp::Add: return finite(e, V(l) + V(r));
        case ExprOp::Sub: return finite(e, V(l) - V(r));
        case ExprOp::Eq: return V(l) == V(r);
        case ExprOp::Ne: return V(l) != V(r);
        default: break;
        }
    } else if (lk == K::Vec2 && rk == K::Float) {
        if (e.op == ExprOp::Mul) return finite(e, V(l) * F(r));
        if (e.op == ExprOp::Div) {
            if (F(r) == 0) fail(e, "division by zero");
            return finite(e, V(l) / F(r));
        }
    } else if (lk == K::Float && rk == K::Vec2 && e.op == ExprOp::Mul) {
        return finite(e, F(l) * V(r));
    }
    if (e.op == ExprOp::Add) return S(l) + S(r);
    if (e.op == ExprOp::Eq) return l == r;
    if (e.op == ExprOp::Ne) return l != r;
    fail(e, "unsupported operation");
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

}  // namespace

Value evaluate(const ir::Expr& e, EvalFrame& f) {
    switch (e.op) {
    case ExprOp::Literal: return fromLiteral(e.value);
    case ExprOp::Param: return (*f.params)[e.index];
    case ExprOp::Const: return (*f.consts)[e.index];
    case ExprOp::Local: return (*f.locals)[e.index];
    case ExprOp::FnArg: return (*f.fnArgs)[e.index];
    case ExprOp::Attr:
        if (e.elem.cls == ir::ElemClass::Edge) return f.graph->edgeAttr((*f.edges)[e.elem.index], e.index);
        return f.graph->nodeAttr((*f.nodes)[e.elem.index], e.index);
    case ExprOp::SelfAttr:
        return f.selfIsEdge ? f.graph->edgeAttr(f.self, e.index) : f.graph->nodeAttr(f.self, e.index);
    case ExprOp::Fact: {
        const bool isEdge = e.elem.cls == ir::ElemClass::Edge;
        return fact(e, f, isEdge, isEdge ? (*f.edges)[e.elem.index] : (*f.nodes)[e.elem.index]);
    }
    case ExprOp::SelfFact: return fact(e, f, f.selfIsEdge, f.self);
    case ExprOp::VecX: return V(evaluate(e.args[0], f)).x;
    case ExprOp::VecY: return V(evaluate(e.args[0], f)).y;
    case ExprOp::Neg: {
        Value v = evaluate(e.args[0], f);
        if (auto* i = std::get_if<long long>(&v)) {
            if (*i == LLONG_MIN) fail(e, "integer overflow");
            return -*i;
        }
        if (auto* d = std::get_if<double>(&v)) return -*d;
        return -V(v);
    }
    case ExprOp::Not: return !B(evaluate(e.args[0], f));
    case ExprOp::And: return B(evaluate(e.args[0], f)) && B(evaluate(e.args[1], f));
    case ExprOp::Or: return B(evaluate(e.args[0], f)) || B(evaluate(e.args[1], f));
    case ExprOp::Cond: return B(evaluate(e.args[0], f)) ? evaluate(e.args[1], f) : evaluate(e.args[2], f);
    case ExprOp::Call: return call(e, f);
    case ExprOp::CallFn: {
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

bool evaluateBool(const ir::Expr& e, EvalFrame& f) { return B(evaluate(e, f)); }
rt::vec2 evaluateVec(const ir::Expr& e, EvalFrame& f) { return V(evaluate(e, f)); }

}  // namespace g2d::interp
