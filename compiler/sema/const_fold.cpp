#include "sema/const_fold.hpp"

#include <climits>
#include <cmath>

#include "g2d/builtins.hpp"
#include "g2d/ops.hpp"
#include "g2d/vec_math.hpp"

namespace g2d::sema {

using ir::Builtin;
using ir::Expr;
using ir::ExprOp;
using ir::TypeKind;
using ir::Value;

double asNumber(const Value& v) {
    if (auto* i = std::get_if<long long>(&v)) return static_cast<double>(*i);
    if (auto* d = std::get_if<double>(&v)) return *d;
    return 0;
}

namespace {

using ir::fromRuntime;
using ir::toRuntime;

// The runtime's own built-in, so a fold gives what a run gives, error for
// error. Random draws, str() and format() are left to the run.
std::optional<Value> foldCall(const Expr& e, const std::vector<Value>& a, std::string* error) {
    const rt::BuiltinCall how = rt::builtinEntry(e.builtin).call;
    if (how != rt::BuiltinCall::Pure && how != rt::BuiltinCall::Variadic) return std::nullopt;
    std::vector<rt::Value> args;
    for (const auto& v : a) args.push_back(toRuntime(v));
    try {
        return fromRuntime(rt::callBuiltin(e.builtin, args.data(), args.size(), nullptr));
    } catch (const rt::OpError& err) {
        if (error && error->empty()) *error = err.what();
        return std::nullopt;
    }
}

// The runtime's own operators; a failure is a compile-time error.
std::optional<Value> foldArith(ExprOp op, const Value& l, const Value& r, std::string* error) {
    try {
        return fromRuntime(rt::binaryOp(*ir::binaryOperator(op), toRuntime(l), toRuntime(r)));
    } catch (const rt::OpError& err) {
        if (error && error->empty()) *error = err.what();
        return std::nullopt;
    }
}

// Each function body and constant is looked into once (a chain of functions
// each calling the previous twice would otherwise cost 2^n).
template <class Pred>
bool anyOnce(const Expr& e, const ir::Program& prog, Pred& pred, std::vector<bool>& seenFns, std::vector<bool>& seenConsts) {
    if (pred(e)) return true;
    for (const auto& a : e.args)
        if (anyOnce(a, prog, pred, seenFns, seenConsts)) return true;
    auto visit = [&](std::vector<bool>& seen, std::size_t i, const Expr& body) {
        if (seen.size() <= i) seen.resize(i + 1, false);
        if (seen[i]) return false;
        seen[i] = true;
        return anyOnce(body, prog, pred, seenFns, seenConsts);
    };
    if (e.op == ExprOp::CallFn) return visit(seenFns, static_cast<std::size_t>(e.index), prog.functions[e.index].body);
    if (e.op == ExprOp::Const) return visit(seenConsts, static_cast<std::size_t>(e.index), prog.consts[e.index].value);
    return false;
}

template <class Pred>
bool any(const Expr& e, const ir::Program& prog, Pred pred) {
    std::vector<bool> seenFns, seenConsts;
    return anyOnce(e, prog, pred, seenFns, seenConsts);
}

}  // namespace

std::optional<Value> fold(const Expr& e, const ir::Program& prog, std::string* error) {
    switch (e.op) {
    case ExprOp::Literal: return e.value;
    case ExprOp::Const: return prog.consts[e.index].folded;
    case ExprOp::VecX:
    case ExprOp::VecY:
    case ExprOp::VecZ: {
        auto v = fold(e.args[0], prog, error);
        if (!v) return std::nullopt;
        if (const auto* p = std::get_if<ir::Vec3>(&*v)) return Value{e.op == ExprOp::VecX ? p->x : e.op == ExprOp::VecY ? p->y : p->z};
        const auto& p = std::get<ir::Vec2>(*v);
        return Value{e.op == ExprOp::VecX ? p.x : p.y};
    }
    case ExprOp::Neg: {
        auto v = fold(e.args[0], prog, error);
        if (!v) return std::nullopt;
        if (auto* i = std::get_if<long long>(&*v)) {
            if (*i == LLONG_MIN) {
                if (error && error->empty()) *error = "integer overflow";
                return std::nullopt;
            }
            return Value{-*i};
        }
        if (auto* d = std::get_if<double>(&*v)) return Value{-*d};
        if (auto* p = std::get_if<ir::Vec3>(&*v)) return Value{ir::Vec3{-p->x, -p->y, -p->z}};
        const auto& p = std::get<ir::Vec2>(*v);
        return Value{ir::Vec2{-p.x, -p.y}};
    }
    case ExprOp::Not: {
        auto v = fold(e.args[0], prog, error);
        if (!v) return std::nullopt;
        return Value{!std::get<bool>(*v)};
    }
    case ExprOp::And:
    case ExprOp::Or: {
        // Either side alone may decide: `x.k > 1 and false` is false.
        const bool decisive = e.op == ExprOp::Or;
        auto l = fold(e.args[0], prog, error);
        if (l && std::get<bool>(*l) == decisive) return Value{decisive};
        auto r = fold(e.args[1], prog, error);
        if (r && std::get<bool>(*r) == decisive) return Value{decisive};
        if (l && r) return Value{!decisive};
        return std::nullopt;
    }
    case ExprOp::Cond: {
        auto c = fold(e.args[0], prog, error);
        if (!c) return std::nullopt;
        return fold(e.args[std::get<bool>(*c) ? 1 : 2], prog, error);
    }
    case ExprOp::Call: {
        std::vector<Value> args;
        for (const auto& a : e.args) {
            auto v = fold(a, prog, error);
            if (!v) return std::nullopt;
            args.push_back(std::move(*v));
        }
        return foldCall(e, args, error);
    }
    case ExprOp::Add: case ExprOp::Sub: case ExprOp::Mul: case ExprOp::Div: case ExprOp::Mod:
    case ExprOp::Lt: case ExprOp::Le: case ExprOp::Gt: case ExprOp::Ge: case ExprOp::Eq: case ExprOp::Ne: {
        auto l = fold(e.args[0], prog, error);
        auto r = fold(e.args[1], prog, error);
        if (!l || !r) return std::nullopt;
        return foldArith(e.op, *l, *r, error);
    }
    // Values known only when the program runs (a function call may draw, or recurse).
    case ExprOp::Param: case ExprOp::Local: case ExprOp::FnArg: case ExprOp::Attr: case ExprOp::SelfAttr:
    case ExprOp::SelfFact: case ExprOp::Placed: case ExprOp::CompoundValue: case ExprOp::Fact: case ExprOp::CallFn:
    case ExprOp::Count: return std::nullopt;
    }
    return std::nullopt;
}

bool usesRandom(const Expr& e, const ir::Program& prog) {
    return any(e, prog, [](const Expr& x) {
        return x.op == ExprOp::Call && rt::builtinEntry(x.builtin).drawsRandom;
    });
}

bool usesParams(const Expr& e, const ir::Program& prog) {
    return any(e, prog, [](const Expr& x) { return x.op == ExprOp::Param; });
}

bool readsElements(const Expr& e) {
    if (e.op == ExprOp::Attr || e.op == ExprOp::Fact) return true;
    for (const auto& a : e.args)
        if (readsElements(a)) return true;
    return false;
}

bool readsLocals(const Expr& e) {
    if (e.op == ExprOp::Local) return true;
    for (const auto& a : e.args)
        if (readsLocals(a)) return true;
    return false;
}

}  // namespace g2d::sema
