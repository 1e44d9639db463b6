// The thesis tool's `.generation` (g2d/generations.hpp): the `generation`
// fact and `pick oldest generation`, through the interpreter. The compiled
// back end is compared byte for byte by compiled.generation (tests/CMakeLists.txt).
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <string>

#include "test_helpers.hpp"

using namespace g2d;

namespace {

test::SnippetRun run(const std::string& source, std::uint64_t seed, std::optional<long long> steps = {}) {
    return test::runSnippet(source, seed, test::verified(steps));
}

rt::NodeId nodeAt(const rt::Graph& g, rt::vec2 p) {
    for (rt::NodeId n = 0; n < g.nodeCapacity(); ++n)
        if (g.nodeAlive(n) && g.pos(n).x == p.x && g.pos(n).y == p.y) return n;
    FAIL("no node at (" << p.x << ", " << p.y << ")");
    return rt::kNoId;
}

std::string kochWith(const std::string& pick) {
    std::ifstream in(std::string(G2D_SOURCE_DIR) + "/examples/koch_snowflake.g2d");
    std::string src(std::istreambuf_iterator<char>(in), {});
    const std::string from = "rule Split pick oldest {";
    REQUIRE(src.find(from) != std::string::npos);
    return src.replace(src.find(from), from.size(), "rule Split " + pick + " {");
}

}  // namespace

TEST_CASE("an application's new elements get one more than the highest generation it matched", "[generation]") {
    // Deep grows a chain from b (generations 1, 2); then Wide rewrites a
    // (generation 0) and the chain's end (2) in one parallel step: each
    // application gives its own new elements their generation, in the same
    // step (so of the same age).
    const auto r = run("node P { done: bool = false; } edge L directed;\n"
                       "axiom { a: P at (0, 0); b: P at (5, 0); }\n"
                       "rule Deep { match { x: P where !x.done and x.pos.x > 4 and x.generation < 2; }\n"
                       "  produce { x { done = true }; y: P at x.pos + (1, 0); x -[L]-> y; } }\n"
                       "rule Wide priority 1 parallel { match { x: P where !x.done; }\n"
                       "  produce { x { done = true }; y: P at x.pos + (0, 1) { done = true }; x -[L]-> y; } }\n",
                       1);
    const rt::Graph& g = r.graph();
    REQUIRE(g.nodeCount() == 6);
    CHECK(g.nodeGeneration(nodeAt(g, {0, 0})) == 0);   // kept elements keep theirs
    CHECK(g.nodeGeneration(nodeAt(g, {5, 0})) == 0);
    CHECK(g.nodeGeneration(nodeAt(g, {6, 0})) == 1);
    CHECK(g.nodeGeneration(nodeAt(g, {7, 0})) == 2);
    const rt::NodeId fromA = nodeAt(g, {0, 1}), fromEnd = nodeAt(g, {7, 1});
    CHECK(g.nodeGeneration(fromA) == 1);
    CHECK(g.nodeGeneration(fromEnd) == 3);
    CHECK(g.nodeAge(fromA) == 3);
    CHECK(g.nodeAge(fromEnd) == 3);
    for (rt::EdgeId e = 0; e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) CHECK(g.edgeGeneration(e) == g.nodeGeneration(g.target(e)));
}

TEST_CASE("a rule reads generation in conditions and picks by it", "[generation]") {
    // Koch's Split with the tool's measure: a segment of level k has
    // generation k (the application matched its parent, of k - 1), and the
    // run reaches the same whole levels as by age.
    const auto byGeneration = run(kochWith("pick oldest generation"), 7, 3 + 12 + 48);
    const rt::Graph& g = byGeneration.graph();
    REQUIRE(g.edgeCount() == 192);
    for (rt::EdgeId e = 0; e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) CHECK(g.edgeGeneration(e) == std::get<long long>(g.edgeAttr(e, 0)));
}

TEST_CASE("pick oldest generation splits the Koch snowflake's segments in the tool's order, not by age", "[generation]") {
    // After the 63 steps to level 3 and 129 more (192, the thesis's
    // picture), 63 level-3 segments are left unsplit. Level 3 was made in
    // steps 16 to 63. By age they go roughly in the order they were made, so
    // none made before step 40 is left; by generation a segment between
    // corners of older levels goes first wherever it lies, and many of the
    // earliest are left (scattered round the flake, as in the thesis).
    auto unsplit = [](const rt::Graph& g, long long& madeBefore40) {
        long long count = 0;
        madeBefore40 = 0;
        for (rt::EdgeId e = 0; e < g.edgeCapacity(); ++e)
            if (g.edgeAlive(e) && std::get<long long>(g.edgeAttr(e, 0)) == 3) {
                ++count;
                if (g.edgeAge(e) < 40) ++madeBefore40;
            }
        return count;
    };
    for (std::uint64_t seed : {1, 2, 3}) {
        long long earlyByAge = 0, earlyByGeneration = 0;
        const auto byAge = run(kochWith("pick oldest"), seed, 192);
        const auto byGeneration = run(kochWith("pick oldest generation"), seed, 192);
        CHECK(unsplit(byAge.graph(), earlyByAge) == 63);
        CHECK(unsplit(byGeneration.graph(), earlyByGeneration) == 63);
        CHECK(earlyByAge == 0);
        CHECK(earlyByGeneration >= 20);
        CHECK(byAge.graph().edgeCount() == byGeneration.graph().edgeCount());
    }
}

TEST_CASE("pick oldest age is pick oldest, and the measure is checked", "[generation]") {
    const std::string grammar = "node P; edge L;\naxiom { a: P; b: P at (1, 0); a -[L]- b; }\nlimit 1;\n"
                                "rule R PICK { match { x: P; y: P; e: x -[L]- y; } produce { x; y; } }\n";
    auto with = [&](const std::string& pick) {
        std::string s = grammar;
        return s.replace(s.find("PICK"), 4, pick);
    };
    const CompileResult age = test::compile(with("pick oldest age"));
    REQUIRE(age.program);
    CHECK(age.program->rules[0].pick == ir::Pick::Oldest);
    CHECK(!age.program->tracksGenerations);
    const CompileResult generation = test::compile(with("pick oldest generation"));
    REQUIRE(generation.program);
    CHECK(generation.program->rules[0].pick == ir::Pick::OldestGeneration);
    CHECK(generation.program->tracksGenerations);
    CHECK(test::firstError(test::compile(with("pick oldest generatoin"))) ==
          "4:20: unknown measure `generatoin` for `pick oldest` (use `age` or `generation`); did you mean `generation`?");
    CHECK(test::firstError(test::compile(with("pick random age"))) == "4:20: `pick random` takes no measure (`age`)");
}
