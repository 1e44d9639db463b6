// The values of element facts, as rules read them.
#include <catch2/catch.hpp>

#include "interp/run_program.hpp"
#include "test_helpers.hpp"

using namespace g2d;

TEST_CASE("an edge's midpoint is halfway between its ends, in 2D and 3D", "[facts]") {
    for (const bool space3d : {false, true}) {
        const std::string text = std::string(space3d ? "space 3d;\n" : "") + R"(
node A;
node M;
edge E directed;
)" + (space3d ? "axiom { a: A at (0, 0, 1); b: A at (2, 4, 3); a -[E]-> b; }\n"
              : "axiom { a: A at (0, 0); b: A at (2, 4); a -[E]-> b; }\n") + R"(
rule Mark { match { a: A; b: A; e: a -[E]-> b; } produce { a; b; e; m: M at e.midpoint; } }
)";
        INFO(text);
        auto compiled = test::compile(text);
        REQUIRE(test::firstError(compiled) == "");
        auto run = interp::runProgram(*compiled.program, interp::defaultParams(*compiled.program), 1, test::verified(1));
        const rt::Graph& g = run.graph();
        REQUIRE(g.nodeCount() == 3);
        const rt::NodeId m = g.nodesOfKind(1)[0];
        CHECK(g.pos3(m).x == 1.0);
        CHECK(g.pos3(m).y == 2.0);
        CHECK(g.pos3(m).z == (space3d ? 2.0 : 0.0));
    }
}
