#include "sema/param_range_checker.hpp"

#include "g2d/value.hpp"
#include "sema/const_fold.hpp"

namespace g2d::sema {

namespace {

// One bound or the step: of the parameter's type and known now, or an error
// (reported) and nothing.
std::optional<double> constantPart(Globals& g, ExprChecker& ec, const ast::Expr& e, const ir::Param& p,
                                   const std::string& part) {
    ExprEnv env;
    env.context = "a parameter's range";
    env.allowRandom = false;
    env.allowElements = false;
    env.allowLocals = false;
    const std::string what = "the " + part + " of parameter `" + p.name + "`";
    auto value = ec.checkAs(e, p.type, env, what);
    if (!value) return std::nullopt;
    std::string error;
    auto folded = fold(*value, g.prog, &error);
    if (!error.empty()) {
        g.diags.error(e.span, error + " in " + what);
        return std::nullopt;
    }
    if (!folded) {
        g.diags.error(e.span, what + " must be a constant (literals and constants only)");
        return std::nullopt;
    }
    return asNumber(*folded);
}

}  // namespace

void checkParamRange(Globals& g, ExprChecker& ec, const ast::ParamDecl& d, ir::Param& p, bool defaultKnown) {
    if (!d.range) return;
    const ast::ParamRange& r = *d.range;
    if (p.type.kind != ir::TypeKind::Int && p.type.kind != ir::TypeKind::Float) {
        g.diags.error(r.span, "a range applies to int and float parameters only; `" + p.name + "` is of type " +
                                  ir::typeName(p.type, g.prog));
        return;
    }
    if (r.stepWord && r.stepWord->name != "step") {
        g.diags.error(r.stepWord->span, "expected `step` or `;` after the range of parameter `" + p.name +
                                            "`, found name `" + r.stepWord->name + "`");
        return;
    }
    const auto lo = constantPart(g, ec, *r.lower, p, "lower bound");
    const auto hi = constantPart(g, ec, *r.upper, p, "upper bound");
    std::optional<double> step;
    if (r.step) {
        step = constantPart(g, ec, *r.step, p, "step");
        if (!step) return;
    }
    if (!lo || !hi) return;
    const std::string range = rt::formatNumber(*lo) + ".." + rt::formatNumber(*hi);
    if (*lo > *hi) {
        g.diags.error(r.span, "the range " + range + " of parameter `" + p.name +
                                  "` is empty: its lower bound is above its upper bound");
        return;
    }
    if (step && !(*step > 0)) {
        g.diags.error(r.step->span, "the step of parameter `" + p.name + "` must be above 0, not " + rt::formatNumber(*step));
        return;
    }
    if (defaultKnown) {
        const double v = asNumber(p.defaultValue);
        if (!(v >= *lo && v <= *hi)) {
            g.diags.error(d.value->span, "the default of parameter `" + p.name + "`, " + rt::formatNumber(v) +
                                             ", is outside its range " + range);
            return;
        }
    }
    p.min = lo;
    p.max = hi;
    p.step = step;
}

}  // namespace g2d::sema
