#include "sema/canvas_checker.hpp"

#include "g2d/ops.hpp"
#include "g2d/view_box.hpp"
#include "sema/const_fold.hpp"

namespace g2d::sema {

void checkCanvas(Globals& g, ExprChecker& ec, const ast::CanvasDecl& d) {
    if (d.to.name != "to") {
        g.diags.error(d.to.span, "expected `to` between the canvas's corners, found name `" + d.to.name + "`");
        return;
    }
    if (g.prog.canvas) {
        auto& diag = g.diags.error(d.span, "the canvas is set twice");
        diag.notes.push_back({g.prog.canvas->span, "the first canvas is here"});
        return;
    }
    // A 3D grammar's SVG is a projection (--view-from): its units are not the grammar's.
    if (g.prog.space3d) {
        g.diags.error(d.span, "`canvas` frames a 2D grammar's drawing; a 3D grammar's SVG is a projection "
                              "(--view-from): frame it with --viewbox X0,Y0,X1,Y1");
        return;
    }
    ExprEnv env;
    env.context = "a canvas";
    env.allowRandom = false;
    env.allowElements = false;
    env.allowLocals = false;
    auto lower = ec.checkAs(*d.lower, ir::kVec2Type, env, "a canvas corner");
    auto upper = ec.checkAs(*d.upper, ir::kVec2Type, env, "a canvas corner");
    if (!lower || !upper) return;
    // Known now (no parameters): checked now, with the words of the run-time check.
    std::string error;
    const auto lo = fold(*lower, g.prog, &error);
    if (!error.empty()) {
        g.diags.error(d.lower->span, error + " in a canvas corner");
        return;
    }
    const auto hi = fold(*upper, g.prog, &error);
    if (!error.empty()) {
        g.diags.error(d.upper->span, error + " in a canvas corner");
        return;
    }
    if (lo && hi) {
        const auto& a = std::get<ir::Vec2>(*lo);
        const auto& b = std::get<ir::Vec2>(*hi);
        try {
            rt::checkedCanvas(rt::vec2{a.x, a.y}, rt::vec2{b.x, b.y});
        } catch (const rt::OpError& e) {
            g.diags.error(d.span, e.what());
            return;
        }
    }
    g.prog.canvas = ir::Canvas{std::move(*lower), std::move(*upper), d.span};
}

}  // namespace g2d::sema
