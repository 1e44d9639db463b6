// Negative conditions asking for a node near a point (lower/near_negative.hpp,
// g2d/near_queries.hpp): which ones the lowering recognises, and that
// incremental matching through the spatial index keeps exactly the matches a
// full search finds, step after step (test::verified()). Both back ends on a
// richer grammar: cli.near_conditions.
#include <catch2/catch.hpp>

#include <string>

#include "interp/run_program.hpp"
#include "lower/rule_facts.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

const std::string kDecls = R"(
node J { hot: bool = false; }
node T { dir: vec2 = (0, 1); }
edge S directed;
axiom { t: T; j: J at (5, 5); }
)";

// RuleInfo of the grammar's first rule, whose match is `match`.
rt::RuleInfo infoOf(const std::string& match) {
    const auto compiled = test::compile(kDecls + "rule R { match { " + match + " } produce { } }");
    INFO(test::firstError(compiled));
    REQUIRE(compiled.program);
    return lower::ruleFacts(*compiled.program, compiled.program->rules[0]).info;
}

}  // namespace

TEST_CASE("a negative condition for a node near a point is searched through the index", "[near]") {
    SECTION("recognised") {
        for (const char* match : {
                 "t: T; not { o: J; where distance(o.pos, t.pos + t.dir) < 1; }",
                 "t: T; not { o: J; where distance(t.pos, o.pos) <= 2.5; }",
                 "t: T; not { o: J; where 3 > distance(o.pos, t.pos); }",
                 "t: T; not { o: J where o.hot; where o.age > 2 and distance(o.pos, t.pos) < t.dir.x + 1; }",
             }) {
            INFO(match);
            const rt::RuleInfo info = infoOf(match);
            CHECK(info.nearKinds == std::vector<int>{0});
            CHECK(info.radius == 0);   // a near condition needs no full search
        }
    }
    SECTION("not recognised: searched in full after every step, as before") {
        for (const char* match : {
                 "t: T; not { o: *; where distance(o.pos, t.pos) < 1; }",                 // a wildcard: every kind
                 "t: T; not { o: J; where distance(o.pos, o.pos + t.dir) < 1; }",         // the centre reads o
                 "t: T; not { o: J; where distance(o.pos, t.pos) < o.age; }",             // the radius reads o
                 "t: T; not { o: J; where distance(o.pos, t.pos) < 1 or o.hot; }",        // not a conjunct
                 "t: T; not { o: J; where distance(o.pos, t.pos) < 1 and o.degree == 0; }",  // o's edges
                 "t: T; not { o: J; p: J; o -[S]-> p; where distance(o.pos, t.pos) < 1; }",  // more than a node
                 "t: T; not { o: J; where distance(o.pos, t.pos) > 1; }",                 // far, not near
             }) {
            INFO(match);
            const rt::RuleInfo info = infoOf(match);
            CHECK(info.nearKinds.empty());
            CHECK(info.radius == -1);
        }
    }
}

TEST_CASE("matches of near conditions stay exact as nodes come, go, move and change", "[near]") {
    // A coral: tips grow where no joint is near (joints come); and joints
    // that move, get or lose the attribute the condition reads, and melt.
    const std::string source = R"(
node J { hot: bool = true; }
node T { dir: vec2 = (0, 1); }
edge S directed;
axiom { a: T at (0, 0) { dir = (0, 1) }; b: T at (0, -1) { dir = (0, -1) }; c: T at (1, 0) { dir = (1, 0) }; }
limit 500;
rule Grow {
    match { t: T; not { o: J where o.hot; where distance(o.pos, t.pos + t.dir) < 0.9; } }
    let turn = uniform(-0.4, 0.4);
    produce weight 4 { j: J at t.pos; t at t.pos + t.dir { dir = rotate(t.dir, turn) }; j -[S]-> t; }
    produce weight 1 { j: J at t.pos; t at t.pos + t.dir { dir = rotate(t.dir, turn + 0.5) };
                       u: T at t.pos + rotate(t.dir, turn - 0.5) { dir = rotate(t.dir, turn - 0.5) }; j -[S]-> t; j -[S]-> u; }
}
rule Drift { match { j: J; } produce { j at j.pos + (uniform(-1, 1), uniform(-1, 1)); } }
rule Cool { match { j: J; } produce { j { hot = !j.hot }; } }
rule Melt priority 1 { match { j: J where !j.hot; } produce { } }
)";
    const auto compiled = test::compile(source);
    INFO(test::firstError(compiled));
    REQUIRE(compiled.program);
    REQUIRE(lower::ruleFacts(*compiled.program, compiled.program->rules[0]).info.nearKinds.size() == 1);
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        INFO("seed " << seed);
        const auto run = interp::runProgram(*compiled.program, interp::defaultParams(*compiled.program), seed, test::verified());
        CHECK(run.derivation.steps == 500);
        CHECK(run.graph().nodeCount() > 100);
    }
}
