#include "sema/layout_checker.hpp"

#include <cmath>
#include <cstdio>
#include <map>

#include "diag/suggest.hpp"
#include "sema/const_fold.hpp"

namespace g2d::sema {

namespace {

ExprEnv layoutEnv() {
    ExprEnv env;
    env.context = "a layout";
    env.allowRandom = false;
    env.allowElements = false;
    env.allowLocals = false;
    return env;
}

// The folded value of a layout property of `type`, or nothing (reported).
std::optional<ir::Value> constant(Globals& g, ExprChecker& ec, const ast::StyleProp& p, ir::Type type) {
    auto v = ec.checkAs(*p.value, type, layoutEnv(), "`" + p.name.name + "`");
    if (!v) return std::nullopt;
    std::string error;
    auto f = fold(*v, g.prog, &error);
    if (!f) {
        g.diags.error(p.value->span, error.empty() ? "`" + p.name.name + "` must be known when the grammar is compiled "
                                                     "(literals, constants and built-ins; no parameters)"
                                                   : error);
        return std::nullopt;
    }
    return f;
}

bool finite(double x) { return std::isfinite(x); }

}  // namespace

void checkLayoutDecl(Globals& g, ExprChecker& ec, const ast::LayoutDecl& d) {
    g.layoutDeclared = true;
    if (d.name.name != "angles") {
        g.diags.error(d.name.span, "unknown layout `" + d.name.name + "`: the one layout is `angles` (Merrell 2023's drawing step)");
        return;
    }
    if (g.prog.angleLayout) {
        auto& diag = g.diags.error(d.span, "`layout angles` is declared twice");
        diag.notes.push_back({g.prog.angleLayout->span, "the first declaration is here"});
        return;
    }
    if (g.prog.space3d) g.diags.error(d.span, "`layout angles` draws 2D grammars only");
    ir::AngleLayout out;
    out.span = d.span;
    std::map<std::string, Span> seen;
    bool haveMin = false, haveMax = false;
    const std::size_t errorsBefore = g.diags.errorCount();
    for (const auto& p : d.props) {
        if (auto [it, fresh] = seen.emplace(p.name.name, p.span); !fresh) {
            g.diags.error(p.name.span, "`" + p.name.name + "` is set twice");
            continue;
        }
        const std::string& n = p.name.name;
        if (n == "canvas_min" || n == "canvas_max") {
            auto v = constant(g, ec, p, ir::kVec2Type);
            if (!v) continue;
            const auto& xy = std::get<ir::Vec2>(*v);
            double* to = n == "canvas_min" ? out.canvasMin : out.canvasMax;
            to[0] = xy.x, to[1] = xy.y;
            (n == "canvas_min" ? haveMin : haveMax) = true;
            if (!finite(xy.x) || !finite(xy.y)) g.diags.error(p.value->span, "`" + n + "` must be finite");
        } else if (n == "proposals" || n == "samples") {
            auto v = constant(g, ec, p, ir::Type::of(ir::TypeKind::Int));
            if (!v) continue;
            const long long k = std::get<long long>(*v);
            if (k < 1 || k > 1000) {
                g.diags.error(p.value->span, "`" + n + "` must be between 1 and 1000");
                continue;
            }
            (n == "proposals" ? out.proposals : out.samples) = static_cast<int>(k);
        } else if (n == "clearance") {
            auto v = constant(g, ec, p, ir::kFloatType);
            if (!v) continue;
            const double c = asNumber(*v);
            if (!(c >= 0) || !finite(c)) {
                g.diags.error(p.value->span, "`clearance` must be a distance: finite and not negative");
                continue;
            }
            out.clearance = c;
        } else if (n == "bend_segment") {
            auto v = constant(g, ec, p, ir::kFloatType);
            if (!v) continue;
            const double x = asNumber(*v);
            if (!(x > 0) || !finite(x)) {
                g.diags.error(p.value->span, "`bend_segment` must be a positive length: bent edges are cut into segments about that long");
                continue;
            }
            out.bendSegment = x;
            if (!out.bendSettings) out.bendSettings = p.name.span;
        } else if (n == "bend_smooth") {
            auto v = constant(g, ec, p, ir::Type::of(ir::TypeKind::Int));
            if (!v) continue;
            const long long k = std::get<long long>(*v);
            if (k < 1 || k > 1000) {
                g.diags.error(p.value->span, "`bend_smooth` must be between 1 and 1000 segments");
                continue;
            }
            out.bendSmooth = static_cast<int>(k);
            if (!out.bendSettings) out.bendSettings = p.name.span;
        } else if (n == "connected") {
            auto v = constant(g, ec, p, ir::kBoolType);
            if (v) out.connected = std::get<bool>(*v);
        } else if (n == "cost") {
            ExprEnv env = layoutEnv();
            env.context = "the cost (it reads literals, constants, parameters, `count(K)`, `nodes` and `edges`)";
            env.counts = true;
            if (auto v = ec.checkAs(*p.value, ir::kFloatType, env, "the cost")) out.cost = ExprChecker::coerce(std::move(*v), ir::kFloatType);
        } else if (n == "temperature") {
            ExprEnv env = layoutEnv();
            env.context = "the temperature (it reads literals, constants and parameters)";
            auto v = ec.checkAs(*p.value, ir::kFloatType, env, "the temperature");
            if (!v) continue;
            std::string error;
            if (auto f = fold(*v, g.prog, &error); f && !(asNumber(*f) > 0 && finite(asNumber(*f)))) {
                g.diags.error(p.value->span, "the temperature must be positive and finite");
                continue;
            }
            out.temperature = ExprChecker::coerce(std::move(*v), ir::kFloatType);
        } else {
            g.diags.error(p.name.span, "unknown property `" + n + "` of `layout angles`" +
                                           suggest(n, {"canvas_min", "canvas_max", "proposals", "samples", "cost", "temperature", "connected", "clearance",
                                                       "bend_segment", "bend_smooth"}));
        }
    }
    if (out.temperature && !out.cost)
        g.diags.error(seen["temperature"], "a temperature without a `cost` does nothing: every drawn proposal is accepted");
    if (haveMin != haveMax) {
        if (g.diags.errorCount() > errorsBefore) return;   // a misspelt or bad canvas property, reported
        g.diags.error(d.span, std::string("`layout angles` has `") + (haveMin ? "canvas_min" : "canvas_max") + "` but not `" +
                                  (haveMin ? "canvas_max" : "canvas_min") + "`");
        return;
    }
    out.ownCanvas = haveMin;
    if (out.ownCanvas && !(out.canvasMin[0] < out.canvasMax[0] && out.canvasMin[1] < out.canvasMax[1]))
        g.diags.error(d.span, "the canvas is empty: `canvas_min` must lie below and left of `canvas_max`");
    g.prog.angleLayout = out;
}

void checkEdgeLayout(Globals& g, ExprChecker& ec, const ast::KindDecl& d) {
    if (!d.hasLayout) return;
    auto it = g.kinds.find(d.name.name);
    if (it == g.kinds.end()) return;
    ir::Kind& kind = g.prog.kinds[static_cast<std::size_t>(it->second)];
    if (d.cls != ast::KindDecl::Class::Edge) {
        g.diags.error(d.name.span, "only edge kinds have a `layout { … }` (an edge's angle and lengths)");
        return;
    }
    if (!d.directed.value_or(false)) {
        g.diags.error(d.name.span, "edge kind `" + d.name.name + "` has a layout, so it must be `directed`: its angle "
                                   "points from source to target");
        return;
    }
    ir::EdgeLayout out;
    out.span = d.span;
    std::map<std::string, Span> seen;
    bool angle = false, minL = false, maxL = false;
    const std::size_t errorsBefore = g.diags.errorCount();
    for (const auto& p : d.layout) {
        const std::string& n = p.name.name;
        if (auto [i, fresh] = seen.emplace(n, p.span); !fresh) {
            g.diags.error(p.name.span, "`" + n + "` is set twice");
            continue;
        }
        if (n == "left" || n == "right") {
            const auto* name = std::get_if<ast::Name>(&p.value->node);
            auto k = name ? g.kinds.find(name->name) : g.kinds.end();
            if (k == g.kinds.end() || g.prog.kinds[static_cast<std::size_t>(k->second)].cls != ir::ElemClass::Face) {
                g.diags.error(p.value->span, "`" + n + "` names the face kind on that side of the edge");
                continue;
            }
            (n == "left" ? out.left : out.right) = k->second;
            continue;
        }
        if (n != "angle" && n != "length" && n != "min_length" && n != "max_length" && n != "unit" && n != "bend") {
            g.diags.error(p.name.span, "unknown layout property `" + n + "`" +
                                           suggest(n, {"angle", "length", "min_length", "max_length", "unit", "bend", "left", "right"}));
            continue;
        }
        auto v = constant(g, ec, p, ir::kFloatType);
        if (!v) continue;
        const double x = asNumber(*v);
        if (!finite(x)) {
            g.diags.error(p.value->span, "`" + n + "` must be finite");
            continue;
        }
        if (n == "bend") {
            if (x < 0 || x >= 3.141592653589793 / 2) {
                g.diags.error(p.value->span, "`bend` must be an angle in radians from 0 to less than pi/2: the most a segment turns");
                continue;
            }
            out.bend = x;
        } else if (n == "unit") {
            if (!(x > 0)) {
                g.diags.error(p.value->span, "`unit` must be positive: lengths are whole multiples of it");
                continue;
            }
            out.unit = x;
        } else if (n == "angle") out.angle = x, angle = true;
        else if (n == "length") out.minLength = out.maxLength = x, minL = maxL = true;
        else if (n == "min_length") out.minLength = x, minL = true;
        else out.maxLength = x, maxL = true;
    }
    if (seen.count("length") && (seen.count("min_length") || seen.count("max_length")))
        g.diags.error(d.name.span, "give `length` (a rigid edge) or `min_length` and `max_length`, not both");
    if (g.diags.errorCount() > errorsBefore) return;   // the property's own error says it
    if (!angle || !minL || !maxL) {
        g.diags.error(d.name.span, "the layout of `" + d.name.name + "` needs `angle` (radians) and its lengths: `length` or "
                                   "`min_length` and `max_length`");
        return;
    }
    if (!(out.maxLength > 0) || out.minLength < 0 || out.minLength > out.maxLength) {
        g.diags.error(d.name.span, "the lengths of `" + d.name.name + "` must satisfy 0 <= min_length <= max_length, max_length > 0");
        return;
    }
    if (out.unit > 0) {
        // Some whole multiple (at least one unit) must lie in the range.
        const double first = std::max(1.0, std::ceil(out.minLength / out.unit - 1e-9)) * out.unit;
        if (!(first <= out.maxLength * (1 + 1e-9))) {
            char text[160];
            std::snprintf(text, sizeof text, "is a whole multiple of its unit %g between %g and %g", out.unit, out.minLength, out.maxLength);
            g.diags.error(d.name.span, "no length of `" + d.name.name + "` " + text);
            return;
        }
    }
    kind.layout = out;
}

void checkAngleLayoutUse(Globals& g, const std::vector<const ast::KindDecl*>& kinds) {
    if (!g.prog.angleLayout) {
        if (g.layoutDeclared) return;   // its error is reported
        for (const auto* d : kinds)
            if (d->hasLayout && d->cls == ast::KindDecl::Class::Edge)
                g.diags.warning(d->name.span, "edge kind `" + d->name.name + "` has a layout, but the grammar has no "
                                              "`layout angles { … }` that uses it");
        return;
    }
    for (const auto* d : kinds)   // a layout block with an error has been reported already
        if (d->cls == ast::KindDecl::Class::Edge && !d->hasLayout)
            g.diags.error(d->span, "with `layout angles`, edge kind `" + d->name.name + "` needs a `layout { angle = …; length = …; }`");
    const ir::AngleLayout& layout = *g.prog.angleLayout;
    if (!layout.ownCanvas && !g.prog.canvas)
        g.diags.error(layout.span, "`layout angles` needs its canvas: declare `canvas (x0, y0) to (x1, y1);` (parameters may set "
                                   "it) or give `canvas_min = (x, y);` and `canvas_max = (x, y);`");
    if (layout.ownCanvas && g.prog.canvas) {
        auto& diag = g.diags.error(layout.span, "the drawing's canvas is given twice: drop `canvas_min` and `canvas_max`, and "
                                                "`layout angles` draws in the grammar's `canvas`");
        diag.notes.push_back({g.prog.canvas->span, "the grammar's canvas is here"});
    }
    bool bends = false;
    for (const auto& k : g.prog.kinds) bends = bends || (k.layout && k.layout->bend > 0);
    if (layout.bendSettings && !bends)
        g.diags.warning(*layout.bendSettings, "no edge kind bends (`bend = A;` in its layout), so the bend settings do nothing");
    if (!g.prog.sequence.empty()) g.diags.error(g.prog.angleLayout->span, "`layout angles` cannot be used with a `sequence`");
    if (g.prog.mergeAll) g.diags.error(g.prog.angleLayout->span, "`layout angles` cannot be used with `merge within`");
    for (const auto& r : g.prog.rules) {
        if (ir::runsParallel(g.prog, r) || ir::inGeneration(g.prog, r))
            g.diags.error(r.span, "rule `" + r.name + "` is parallel, but with `layout angles` each application is drawn on "
                                  "its own");
        if (r.merge || r.intersect) g.diags.error(r.span, "rule `" + r.name + "`: `merge` and `intersect` do not combine with `layout angles`");
        for (const auto& d : r.daughters) {
            for (const auto& n : d.nodes)
                if (n.motherNode >= 0 && n.position)
                    g.diags.error(n.span, "node `" + n.name + "` keeps the place the drawing step gave it (`layout angles`): "
                                          "remove its `at`");
            if (!d.loops.empty() || !d.splits.empty() || !d.inserts.empty())
                g.diags.error(d.span, "with `layout angles`, a daughter makes its nodes and edges one by one (no `for`, "
                                      "`split` or `insert`)");
        }
    }
}

}  // namespace g2d::sema
