// `canvas LOWER to UPPER;` and --viewbox: the parser (neither word reserved),
// the checker's located errors, the IR, and the SVG's exact frame.
#include <catch2/catch.hpp>

#include "g2d/ops.hpp"
#include "g2d/svg_writer.hpp"
#include "g2d/view_box.hpp"
#include "parse/parser.hpp"
#include "test_helpers.hpp"

using namespace g2d;
using g2d::test::compile;
using g2d::test::firstError;
using g2d::test::prelude;

namespace {

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

rt::DrawItem dot(rt::vec2 p) {
    rt::DrawItem it;
    it.a = p;
    return it;
}

}  // namespace

TEST_CASE("canvas parses as a declaration with two corner expressions", "[parser][canvas]") {
    SourceManager sm;
    Diagnostics diags;
    const FileId id = sm.add("t.g2d", "const m = 1;\ncanvas (-m, 0) to (4, 3 * m);\n");
    const auto program = parseFile(sm, id, diags);
    REQUIRE(program);
    REQUIRE(program->decls.size() == 2);
    const auto& c = std::get<ast::CanvasDecl>(program->decls[1].decl);
    CHECK(std::holds_alternative<ast::VecLit>(c.lower->node));
    CHECK(std::holds_alternative<ast::VecLit>(c.upper->node));
    CHECK(c.to.name == "to");
    CHECK(c.span.line == 2);
    CHECK(c.span.col == 1);
}

TEST_CASE("canvas and to are not reserved: they still name kinds, attributes and parameters", "[parser][sema][canvas]") {
    auto r = compile("param to: float = 2;\n"
                     "node canvas { canvas: float = 1; to: int = 0; }\n"
                     "canvas (0, 0) to (to, to);\n"
                     "axiom { canvas: canvas at (0, 0) { canvas = to }; }\n");
    INFO(firstError(r));
    REQUIRE(r.program);
    REQUIRE(r.program->canvas);
}

TEST_CASE("canvas errors are located", "[sema][canvas]") {
    struct Case {
        const char* what;
        std::string source;   // after the prelude's 4 lines
        std::string expected;
    };
    const std::vector<Case> cases = {
        {"twice", "canvas (0, 0) to (1, 1);\ncanvas (0, 0) to (2, 2);", "6:1: the canvas is set twice"},
        {"inverted", "canvas (1, 0) to (0, 1);",
         "5:1: the canvas is empty: its first corner (1, 0) must lie below and left of its second (0, 1)"},
        {"empty", "canvas (0, 2) to (1, 2);",
         "5:1: the canvas is empty: its first corner (0, 2) must lie below and left of its second (1, 2)"},
        {"not a vector", "canvas 5 to (1, 1);", "5:8: a canvas corner must be vec2, but this is int"},
        {"not numbers", "canvas (0, \"a\") to (1, 1);", "5:12: the y of a vector must be float, but this is string"},
        {"another word than to", "canvas (0, 0) upto (1, 1);",
         "5:15: expected `to` between the canvas's corners, found name `upto`"},
        {"random", "canvas (0, 0) to (1, uniform(1, 2));", "5:22: random function `uniform` cannot be used in a canvas"},
        {"division by zero", "canvas (0, 0) to (1 / 0, 1);", "5:18: division by zero in a canvas corner"},
    };
    for (const auto& c : cases) {
        INFO(c.what << "\n" << c.source);
        auto r = compile(prelude() + c.source);
        CHECK(firstError(r) == c.expected);
        CHECK_FALSE(r.program.has_value());
    }
    // A 3D grammar (not after the prelude, whose axiom is 2D).
    auto r3 = compile("space 3d;\nnode P;\naxiom { a: P at (0, 0, 0); }\ncanvas (0, 0) to (1, 1);\n");
    CHECK(firstError(r3) == "4:1: `canvas` frames a 2D grammar's drawing; a 3D grammar's SVG is a projection "
                           "(--view-from): frame it with --viewbox X0,Y0,X1,Y1");
}

TEST_CASE("the IR keeps the canvas corners, parameters unfolded", "[ir][canvas]") {
    auto r = compile(prelude() + "param top: float = 3;\ncanvas (-1, -1) to (2, top);\n");
    REQUIRE(r.program);
    REQUIRE(r.program->canvas);
    CHECK(r.program->canvas->span.line == 6);
    CHECK(r.program->canvas->upper.type == ir::kVec2Type);
    auto none = compile(prelude());
    REQUIRE(none.program);
    CHECK_FALSE(none.program->canvas);
}

TEST_CASE("a fixed viewBox is written exactly, without a margin", "[svg][canvas]") {
    const std::vector<rt::DrawItem> items = {dot({0, 0}), dot({9, 9})};
    rt::SvgOptions options;
    options.viewBox = rt::ViewBox{-1, 0, 3, 2};
    const std::string svg = rt::writeSvg(items, {}, options);
    CHECK(contains(svg, "width=\"4cm\" height=\"2cm\" viewBox=\"-1 -2 4 2\""));
    CHECK(contains(svg, "cx=\"9\""));   // outside: written, and clipped by the viewer
    // The top is the box's own y1, not y0 + height (which may round), and never -0.
    options.viewBox = rt::checkedCanvas({0.1, -0.3}, {0.3, 0.0});
    CHECK(contains(rt::writeSvg(items, {}, options), "viewBox=\"0.1 0 0.19999999999999998 0.3\""));
    const std::string fitted = rt::writeSvg(items, {});
    CHECK_FALSE(contains(fitted, "viewBox=\"-1 -2 4 2\""));
}

TEST_CASE("canvas corners and --viewbox text are checked", "[svg][canvas]") {
    CHECK_THROWS_WITH(rt::checkedCanvas({1, 0}, {0, 1}),
                      "the canvas is empty: its first corner (1, 0) must lie below and left of its second (0, 1)");
    CHECK_THROWS_AS(rt::checkedCanvas({-1e308, 0}, {1e308, 1}), rt::OpError);
    std::string error;
    const auto box = rt::parseViewBox(" -10, -5 ,10,15", error);
    REQUIRE(box);
    CHECK(box->x0 == -10);
    CHECK(box->y0 == -5);
    CHECK(box->x1 == 10);
    CHECK(box->y1 == 15);
    for (const char* bad : {"1,2,3", "1,2,3,4,5", "a,b,c,d", "", "0,0,1e999,1", "1,,2,3"}) {
        INFO(bad);
        CHECK_FALSE(rt::parseViewBox(bad, error));
        CHECK(error == "expected four numbers X0,Y0,X1,Y1 (the lower left and the upper right corner, y up)");
    }
    CHECK_FALSE(rt::parseViewBox("0,0,0,1", error));
    CHECK(error == "the box is empty: X0 must be less than X1 and Y0 less than Y1");
}
