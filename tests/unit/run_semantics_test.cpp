// The derivation semantics of the thesis, rule by rule, through the interpreter.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <array>
#include <fstream>
#include <iterator>
#include <set>

#include "g2d/json_writer.hpp"
#include "g2d/svg_writer.hpp"
#include "interp/drawing.hpp"
#include "interp/interpreted_rules.hpp"
#include "interp/run_program.hpp"
#include "run_semantics_helpers.hpp"
#include "test_helpers.hpp"

using namespace g2d;
using g2d::test::compile;
using g2d::test::derive;
using g2d::test::countNodes;
using g2d::test::kindIndex;
using g2d::test::koch;

namespace {

using Segment = std::pair<rt::vec2, rt::vec2>;

// The level-n Koch curve on one directed edge, computed independently.
void kochSegments(rt::vec2 p, rt::vec2 q, int level, std::vector<Segment>& out) {
    if (level == 0) { out.push_back({p, q}); return; }
    const rt::vec2 v = q - p;
    const rt::vec2 a = p + v / 3.0, b = p + v / 2.0 + std::sqrt(3.0) / 6.0 * rt::vec2(-v.y, v.x), c = p + v * 2.0 / 3.0;
    kochSegments(p, a, level - 1, out);
    kochSegments(a, b, level - 1, out);
    kochSegments(b, c, level - 1, out);
    kochSegments(c, q, level - 1, out);
}

std::vector<std::array<long long, 4>> rounded(const std::vector<Segment>& segs) {
    std::vector<std::array<long long, 4>> out;
    for (const auto& [a, b] : segs)
        out.push_back({std::llround(a.x * 1e8), std::llround(a.y * 1e8), std::llround(b.x * 1e8), std::llround(b.y * 1e8)});
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST_CASE("the Koch snowflake is exact for levels 0 to 4", "[run][koch]") {
    for (int level = 0; level <= 4; ++level) {
        auto r = derive(koch(), 1, {}, {{"max_lod", static_cast<long long>(level)}});
        const rt::Graph& g = r.run.graph();
        CHECK(g.edgeCount() == static_cast<std::size_t>(3 * std::pow(4, level)));
        CHECK(r.run.derivation.stopped == rt::StopReason::Terminal);
        std::vector<Segment> expected, actual;
        const rt::vec2 a{-4, 0}, b{0, 6.93}, c{4, 0};
        kochSegments(a, b, level, expected);
        kochSegments(b, c, level, expected);
        kochSegments(c, a, level, expected);
        for (rt::EdgeId e = 0; e < g.edgeCapacity(); ++e)
            if (g.edgeAlive(e)) actual.push_back({g.pos(g.source(e)), g.pos(g.target(e))});
        INFO("level " << level);
        CHECK(rounded(actual) == rounded(expected));
    }
}

TEST_CASE("spikes point outward: every vertex lies outside or on the triangle", "[run][koch]") {
    auto r = derive(koch(), 1, {}, {{"max_lod", 1LL}});
    // Level 1: the three spike tips are outside the triangle (-4,0), (0,6.93), (4,0).
    int outside = 0;
    for (rt::NodeId n : r.run.graph().allNodes()) {
        const rt::vec2 p = r.run.graph().pos(n);
        if (p.y < -1e-9 || p.y > 6.93 * (1 - std::abs(p.x) / 4) + 1e-9) ++outside;
    }
    CHECK(outside == 3);
}

TEST_CASE("single-pushout deletion removes dangling edges", "[run][spo]") {
    auto r = derive("node P; node Hub; edge L;\n"
                    "axiom { h: Hub at (0, 0); a: P at (1, 0); b: P at (2, 0); c: P at (3, 0); h -[L]- a; h -[L]- b; a -[L]- c; }\n"
                    "rule DropHub { match { h: Hub; } produce { } }\n");
    const auto& g = r.run.graph();
    CHECK(r.run.derivation.steps == 1);
    CHECK(g.nodeCount() == 3);
    CHECK(g.edgeCount() == 1);  // only a–c survives
}

TEST_CASE("mapping by name: kept elements keep or change attributes, new ones get defaults", "[run][mapping]") {
    auto r = derive("node P { n: int = 7; tag: string = \"x\"; }\n"
                    "axiom { a: P at (0, 0) { n = 1 }; }\n"
                    "rule R { match { a: P where a.n == 1; } produce { a { n = a.n + 1 }; b: P at (1, 0); } }\n");
    const auto& g = r.run.graph();
    CHECK(r.run.derivation.steps == 1);
    REQUIRE(g.nodeCount() == 2);
    CHECK(std::get<long long>(g.nodeAttr(0, 0)) == 2);
    CHECK(std::get<std::string>(g.nodeAttr(0, 1)) == "x");
    CHECK(std::get<long long>(g.nodeAttr(1, 0)) == 7);
    CHECK(g.nodeAge(1) == 1);
}

TEST_CASE("wildcards match any kind and stay unchanged", "[run][wildcard]") {
    auto r = derive("node P; node Q { w: int = 5; } edge L directed;\n"
                    "axiom { p: P at (0, 0); q: Q at (1, 0); r: P at (2, 0); p -[L]-> q; p -[L]-> r; }\n"
                    "rule Cut { match { p: P; x: *; e: p -[L]-> x; } produce { p; x; } }\n");
    const auto& g = r.run.graph();
    CHECK(r.run.derivation.steps == 2);
    CHECK(g.edgeCount() == 0);
    CHECK(g.nodeCount() == 3);
    CHECK(std::get<long long>(g.nodeAttr(1, 0)) == 5);
}

TEST_CASE("element, cross-element and negative conditions", "[run][conditions]") {
    auto r = derive("node P { v: int = 0; } edge L directed;\n"
                    "axiom { a: P at (0, 0) { v = 1 }; b: P at (1, 0) { v = 2 }; c: P at (2, 0) { v = 3 }; "
                    "a -[L]-> b; b -[L]-> c; c -[L]-> a; }\n"
                    "rule Mark { match { x: P where x.v > 0; y: P; x -[L]-> y; where x.v < y.v; "
                    "not { z: P; y -[L]-> z where z.v == 1; } } produce { x { v = -x.v }; y; } }\n");
    // x→y with x.v < y.v: a→b (1<2) and b→c (2<3), but b→c is first rejected by the
    // NAC (c → a with a.v == 1). Step 1 rewrites a; then a.v is -1, so step 2 rewrites b;
    // c→a fails the cross-element condition (3 < -1), so the derivation ends.
    const auto& g = r.run.graph();
    CHECK(std::get<long long>(g.nodeAttr(0, 0)) == -1);
    CHECK(std::get<long long>(g.nodeAttr(1, 0)) == -2);
    CHECK(std::get<long long>(g.nodeAttr(2, 0)) == 3);
    CHECK(r.run.derivation.steps == 2);
}

TEST_CASE("the ordering option keeps the sketch's x and y order", "[run][ordered]") {
    const std::string square = "node P; edge L;\n"
                               "axiom { a: P at (0, 0); b: P at (1, 0); c: P at (1, 1); d: P at (0, 1); "
                               "a -[L]- b; b -[L]- c; c -[L]- d; d -[L]- a; }\n";
    const std::string pattern = "{ match { p: P @ (0, 0); q: P @ (1, 0); r: P @ (1, 1); p -[L]- q; q -[L]- r; } produce { p; q; r; } }\n";
    auto countMatches = [&](const std::string& options) {
        auto c = compile(square + "rule R " + options + " " + pattern);
        REQUIRE(c.program);
        rt::Rng rng(1);
        interp::ProgramState st;
        rt::Graph g = interp::startRun(*c.program, interp::defaultParams(*c.program), rng, st);
        interp::InterpretedRules rules(st);
        rt::MatchBuffer matches;
        matches.reset(3, 2);
        rules.findMatches(0, g, matches);
        return matches.size();
    };
    CHECK(countMatches("") == 8);         // every path of length two around the square
    // p=a, q=b, r=c keeps the order; so does its mirror p=a, q=d, r=c, because ties
    // are allowed, as in the thesis's tool (q and r share a sketch x, d and c a host y).
    CHECK(countMatches("ordered") == 2);
}

TEST_CASE("pick oldest applies to the oldest match first", "[run][oldest]") {
    // Each step extends the chain at one end; oldest always picks the edge made first.
    auto r = derive("node P { seen: bool = false; } edge L directed { n: int = 0; }\n"
                    "axiom { a: P at (0, 0); b: P at (1, 0); c: P at (2, 0); a -[L { n = 1 }]-> b; b -[L { n = 2 }]-> c; }\n"
                    "limit 1;\n"
                    "rule Grow pick oldest { match { x: P; y: P; e: x -[L]-> y; } "
                    "produce { x; y; e { n = 0 }; z: P at (0, 5); y -[L { n = e.n * 10 }]-> z; } }\n");
    // Both edges have age 0: a tie broken at random; after one step exactly one new edge exists with n 10 or 20.
    const auto& g = r.run.graph();
    REQUIRE(g.edgeCount() == 3);
    const long long n = std::get<long long>(g.edgeAttr(2, 0));
    CHECK((n == 10 || n == 20));
    // With one axiom edge older than the other, oldest is deterministic.
    auto r2 = derive("node P; edge L directed { n: int = 0; }\n"
                     "axiom { a: P at (0, 0); b: P at (1, 0); a -[L { n = 1 }]-> b; }\n"
                     "limit 3;\n"
                     "rule Grow pick oldest { match { x: P; y: P; e: x -[L]-> y where e.n > 0; } "
                     "produce { x; y; e { n = 0 }; z: P at (0, 5); y -[L { n = e.n + 1 }]-> z; w: P at (0, 6); y -[L { n = 100 }]-> w; } }\n");
    // Step 1 rewrites the axiom edge (age 0); step 2 must take one of the two edges of age 1,
    // never an edge of age 2 made in step 2.
    std::set<long long> ages;
    for (rt::EdgeId e = 0; e < r2.run.graph().edgeCapacity(); ++e)
        if (std::get<long long>(r2.run.graph().edgeAttr(e, 0)) == 0) ages.insert(r2.run.graph().edgeAge(e));
    CHECK(ages == std::set<long long>{0, 1});
}

TEST_CASE("daughters are chosen by weight", "[run][weights]") {
    const std::string src = "node P; node A; node B;\naxiom { p: P at (0, 0); }\n"
                            "rule R { match { p: P; } produce weight 1 { a: A at (0, 0); } produce weight 3 { b: B at (0, 0); } }\n";
    auto c = compile(src);
    REQUIRE(c.program);
    const int kindB = kindIndex(*c.program, "B");
    int bs = 0;
    const int runs = 4000;
    for (int seed = 0; seed < runs; ++seed) {
        auto run = interp::runProgram(*c.program, {}, static_cast<std::uint64_t>(seed), test::verified());
        bs += static_cast<int>(countNodes(run.graph(), kindB));
    }
    // Expected 3/4; the standard deviation of the count is sqrt(n p (1-p)) ≈ 27.4.
    CHECK(std::abs(bs - runs * 3 / 4) < 5 * 28);
}

TEST_CASE("weights read from the match are evaluated per application, and 0 is never chosen", "[run][weights]") {
    // p.w is 3 for the first node and 0 for the second: its A-daughter is
    // three times as likely there, and never chosen at the second.
    const std::string src = "node P { w: float = 0; } node A; node B; node C;\n"
                            "axiom { p: P at (0, 0) { w = 3 }; q: P at (1, 0); }\n"
                            "rule R { match { p: P; } produce weight p.w { a: A at p.pos; } produce weight 1 { b: B at p.pos; } }\n";
    auto c = compile(src);
    REQUIRE(c.program);
    const int kindA = kindIndex(*c.program, "A");
    int asAtFirst = 0;
    const int runs = 4000;
    for (int seed = 0; seed < runs; ++seed) {
        auto run = interp::runProgram(*c.program, {}, static_cast<std::uint64_t>(seed), test::verified());
        const rt::Graph& g = run.graph();
        for (rt::NodeId n = 0; n < g.nodeCapacity(); ++n) {
            if (!g.nodeAlive(n) || g.nodeKind(n) != kindA) continue;
            CHECK(g.pos(n).x == 0);   // never at q, whose weight is 0
            ++asAtFirst;
        }
    }
    // Expected 3/4 at p; the standard deviation of the count is about 27.4.
    CHECK(std::abs(asAtFirst - runs * 3 / 4) < 5 * 28);
}

TEST_CASE("a match whose weights are all 0, or one negative, stops the run at the weight", "[run][weights]") {
    const std::string kinds = "node P { w: float = 0; }\naxiom { p: P at (0, 0) { w = -1 }; }\n";
    SECTION("all 0") {
        auto c = compile("node P { w: float = 0; }\naxiom { p: P at (0, 0); }\n"
                         "rule R { match { p: P; } produce weight p.w { } produce weight p.w * 2 { p; } }\n");
        REQUIRE(c.program);
        try {
            interp::runProgram(*c.program, {}, 1, test::verified());
            FAIL("expected an error");
        } catch (const interp::EvalError& e) {
            CHECK(std::string(e.what()) == "every daughter's weight is 0 for this match: a match that must not be "
                                           "rewritten belongs in the match's conditions (`where`)");
            CHECK(e.span.line == 3);
            CHECK(e.span.col == 41);
        }
    }
    SECTION("negative") {
        auto c = compile(kinds + "rule R { match { p: P; } produce weight 1 { } produce weight p.w { p; } }\n");
        REQUIRE(c.program);
        try {
            interp::runProgram(*c.program, {}, 1, test::verified());
            FAIL("expected an error");
        } catch (const interp::EvalError& e) {
            CHECK(std::string(e.what()) == "a weight must be 0 or more, but this is -1 for this match");
            CHECK(e.span.line == 3);
            CHECK(e.span.col == 62);
        }
    }
}

TEST_CASE("priorities and both kinds of limits, as in the thesis's §4.1 example", "[run][limits]") {
    // Priority 0 could run forever; it is limited to 100. Priority 1 consumes tokens.
    auto grammar = [](int tokens) {
        std::string axiom = "axiom { c: Counter at (0, 0);";
        for (int i = 0; i < tokens; ++i) axiom += " t" + std::to_string(i) + ": Token at (" + std::to_string(i) + ", 1);";
        return "node Counter { n: int = 0; } node Token;\n" + axiom + " }\n"
               "limit 500;\npriority 0 limit 100;\n"
               "rule Count priority 0 { match { c: Counter; } produce { c { n = c.n + 1 }; } }\n"
               "rule Eat priority 1 { match { t: Token; } produce { } }\n";
    };
    auto terminal = derive(grammar(200));
    CHECK(terminal.run.derivation.steps == 300);
    CHECK(terminal.run.derivation.stopped == rt::StopReason::Terminal);
    CHECK(std::get<long long>(terminal.run.graph().nodeAttr(0, 0)) == 100);
    auto limited = derive(grammar(600));
    CHECK(limited.run.derivation.steps == 500);
    CHECK(limited.run.derivation.stopped == rt::StopReason::StepLimit);
    CHECK(limited.run.graph().nodeCount() == 1 + 200);  // 400 tokens eaten after 100 counts
}

TEST_CASE("lower priority values go first, equal priorities in random order", "[run][priorities]") {
    auto r = derive("node S; node A; node B;\naxiom { s: S at (0, 0); }\nlimit 1;\n"
                    "rule Late priority 5 { match { s: S; } produce { s; b: B at (0, 0); } }\n"
                    "rule Early priority -1 { match { s: S; } produce { s; a: A at (0, 0); } }\n");
    CHECK(countNodes(r.run.graph(), 1) == 1);
    CHECK(countNodes(r.run.graph(), 2) == 0);
    const std::string tie = "node S; node A; node B;\naxiom { s: S at (0, 0); }\nlimit 1;\n"
                            "rule First { match { s: S; } produce { s; a: A at (0, 0); } }\n"
                            "rule Second { match { s: S; } produce { s; b: B at (0, 0); } }\n";
    std::set<std::size_t> outcomes;
    for (int seed = 0; seed < 20; ++seed) outcomes.insert(countNodes(derive(tie, seed).run.graph(), 1));
    CHECK(outcomes == std::set<std::size_t>{0, 1});
}

TEST_CASE("a parallel step rewrites every non-overlapping match at once", "[run][parallel]") {
    std::string src = koch();
    src.replace(src.find("rule Split pick oldest"), 22, "rule Split parallel");
    for (int level = 1; level <= 5; ++level) {
        auto r = derive(src, 3, level, {{"max_lod", 10LL}});
        CHECK(r.run.derivation.steps == level);
        CHECK(r.run.graph().edgeCount() == static_cast<std::size_t>(3 * std::pow(4, level)));
    }
    // `priority P parallel` makes every rule of that priority parallel.
    std::string byPriority = koch();
    byPriority.replace(byPriority.find("rule Split pick oldest"), 22, "priority 0 parallel;\nrule Split");
    auto p = derive(byPriority, 3, 3, {{"max_lod", 10LL}});
    CHECK(p.run.graph().edgeCount() == 3 * 64u);
    // Overlapping matches: two rules' matches share a deleted node; only one applies per step.
    auto r = derive("node P; edge L;\naxiom { a: P at (0, 0); b: P at (1, 0); c: P at (2, 0); a -[L]- b; b -[L]- c; }\n"
                    "limit 1;\nrule Merge parallel { match { x: P; y: P; x -[L]- y; } produce { x; } }\n");
    CHECK(r.run.graph().nodeCount() == 2);
}

TEST_CASE("a parallel step rewrites the taken matches in the set's order", "[run][parallel]") {
    // The ten P nodes' matches are drawn in random order but rewritten in the
    // match set's (here the nodes' own), so the k-th new Q node is P k's.
    std::string ps;
    for (int i = 0; i < 10; ++i) ps += " p" + std::to_string(i) + ": P at (" + std::to_string(i) + ", 0);";
    for (std::uint64_t seed : {1, 2, 3}) {
        auto r = derive("node P; node Q;\naxiom {" + ps + " }\nlimit 1;\n"
                        "rule Mark parallel { match { x: P; } produce { x; y: Q at x.pos + (0, 1); } }\n", seed);
        const auto& g = r.run.graph();
        REQUIRE(g.nodeCount() == 20);
        for (rt::NodeId k = 0; k < 10; ++k) CHECK(g.pos(10 + k).x == static_cast<double>(k));
    }
}

TEST_CASE("automatic placement follows the match (thesis Fig. 5.3)", "[run][placement]") {
    auto r = derive("node V; edge E directed;\naxiom { a: V at (0, 0); b: V at (1, 1); a -[E]-> b; }\nlimit 1;\n"
                    "rule Double { match { x: V @ (0, 0); y: V @ (1, 0); x -[E]-> y; } "
                    "produce { x; y; x2: V @ (-0.5, 0); y2: V @ (1.5, 0); } }\n");
    const auto& g = r.run.graph();
    REQUIRE(g.nodeCount() == 4);
    CHECK(g.pos(2).x == Approx(-0.5));
    CHECK(g.pos(2).y == Approx(-0.5));
    CHECK(g.pos(3).x == Approx(1.5));
    CHECK(g.pos(3).y == Approx(1.5));
    // Scaling follows the extents along the match's direction and across it.
    auto s = derive("node V; edge E directed;\naxiom { a: V at (0, 0); b: V at (4, 0); c: V at (4, 2); a -[E]-> b; b -[E]-> c; }\nlimit 1;\n"
                    "rule Mid { match { x: V @ (0, 0); y: V @ (2, 0); z: V @ (2, 1); x -[E]-> y; y -[E]-> z; } "
                    "produce { x; y; z; m: V @ (1, 0.5); } }\n");
    CHECK(s.run.graph().pos(3).x == Approx(2.0));
    CHECK(s.run.graph().pos(3).y == Approx(1.0));
    // Along an axis where the mother sketch is flat the sketch's own scale (1) holds.
    auto t = derive("node V; edge E;\naxiom { a: V at (0, 0); b: V at (4, 0); a -[E]- b; }\nlimit 1;\n"
                    "rule Out ordered { match { x: V @ (0, 0); y: V @ (2, 0); x -[E]- y; } "
                    "produce { x; y; m: V @ (1, 1); } }\n");
    CHECK(t.run.graph().pos(2).x == Approx(2.0));
    CHECK(t.run.graph().pos(2).y == Approx(1.0));
    // A least-squares line points right: a mirrored match is not turned upside down.
    auto mirror = derive("node V; edge E;\naxiom { a: V at (0, 0); b: V at (4, 0); a -[E]- b; }\nlimit 1;\n"
                         "rule Up { match { x: V @ (0, 0); y: V @ (2, 0); x -[E]- y where x.pos.x > y.pos.x; } "
                         "produce { x; y; m: V @ (1, 1); } }\n");
    CHECK(mirror.run.graph().pos(2).y == Approx(1.0));
}

TEST_CASE("automatic placement scales by the whole match, even when one node is kept", "[run][placement]") {
    // The rule is drawn on a 10 × 10 square; the host square is 1 × 1 (thesis §5.3: scale
    // = extent of H^M / extent of M), so (4.5, 4.5) lands near the top-right corner.
    auto r = derive("node V; node Centre; edge E; edge L;\n"
                    "axiom { a: V at (0, 0); b: V at (0, 1); c: V at (1, 1); d: V at (1, 0); m: Centre at (0.5, 0.5);\n"
                    "        a -[E]- b; b -[E]- c; c -[E]- d; d -[E]- a; m -[L]- b; }\n"
                    "rule Fill ordered {\n"
                    "  match { bl: V @ (-5, -5); tl: V @ (-5, 5); tr: V @ (5, 5); br: V @ (5, -5); m: Centre @ (0, 0);\n"
                    "          bl -[E]- tl; tl -[E]- tr; tr -[E]- br; br -[E]- bl; m -[L]- tl; }\n"
                    "  produce { m; p: V @ (4.5, 4.5); }\n"
                    "}\nlimit 1;\n");
    CHECK(r.run.graph().pos(5).x == Approx(0.95));
    CHECK(r.run.graph().pos(5).y == Approx(0.95));
}

TEST_CASE("automatic placement on a square (no principal axis) is exact", "[run][placement]") {
    auto r = derive("node V; edge E;\n"
                    "axiom { a: V at (0.1, 0.2); b: V at (0.1, 1.2); c: V at (1.1, 1.2); d: V at (1.1, 0.2);\n"
                    "        a -[E]- b; b -[E]- c; c -[E]- d; d -[E]- a; }\n"
                    "rule Mark ordered {\n"
                    "  match { bl: V @ (-5, -5); tl: V @ (-5, 5); tr: V @ (5, 5); br: V @ (5, -5);\n"
                    "          e1: bl -[E]- tl; e2: tl -[E]- tr; e3: tr -[E]- br; e4: br -[E]- bl; }\n"
                    "  produce { e1; e2; e3; e4; m: V @ (0, 5); }\n"
                    "}\nlimit 1;\n");
    CHECK(r.run.graph().pos(4).x == Approx(0.6));
    CHECK(r.run.graph().pos(4).y == Approx(1.2));
}

TEST_CASE("`at` can refine the automatic position through `placed`", "[run][placement]") {
    auto r = derive("node V; edge E directed;\naxiom { a: V at (0, 0); b: V at (1, 1); a -[E]-> b; }\nlimit 1;\n"
                    "rule Double { match { x: V @ (0, 0); y: V @ (1, 0); x -[E]-> y; } "
                    "produce { x; y; z: V @ (1.5, 0) at (placed.x, 7); } }\n");
    CHECK(r.run.graph().pos(2).x == Approx(1.5));
    CHECK(r.run.graph().pos(2).y == Approx(7.0));
}

TEST_CASE("same grammar and seed give byte-identical SVG and JSON", "[run][determinism]") {
    std::ifstream in(std::string(G2D_SOURCE_DIR) + "/examples/tree.g2d");
    const std::string tree(std::istreambuf_iterator<char>(in), {});
    auto output = [&](std::uint64_t seed) {
        auto r = derive(tree, seed);
        const auto& prog = *r.compiled.program;
        return rt::writeSvg(interp::drawItems(r.run.graph(), r.run.state()), prog.svgDefs) +
               rt::writeJson(r.run.graph(), interp::jsonSchema(prog), {{"seed", static_cast<long long>(seed)}});
    };
    CHECK(output(5) == output(5));
    CHECK(output(5) != output(6));
}

TEST_CASE("the Koch snowflake has the thesis's 1158 elements after 192 steps", "[run][koch]") {
    auto r = derive(koch(), 1, 192);
    CHECK(r.run.derivation.steps == 192);
    CHECK(r.run.graph().nodeCount() + r.run.graph().edgeCount() == 1158);
}

TEST_CASE("the tree reaches the thesis's 803 elements after 200 steps", "[run][tree]") {
    std::ifstream in(std::string(G2D_SOURCE_DIR) + "/examples/tree.g2d");
    const std::string tree(std::istreambuf_iterator<char>(in), {});
    for (std::uint64_t seed : {1, 2, 3}) {
        auto r = derive(tree, seed);
        CHECK(r.run.derivation.steps == 200);
        CHECK(r.run.graph().nodeCount() + r.run.graph().edgeCount() == 803);
    }
}

TEST_CASE("run-time errors name the expression", "[run][errors]") {
    auto c = compile("node P { d: float = 0; }\naxiom { p: P at (0, 0); }\n"
                     "rule R { match { p: P; } produce { p at (1 / p.d, 0); } }\n");
    REQUIRE(c.program);
    interp::RunFailure failure;
    try {
        interp::runProgram(*c.program, {}, 1, test::verified(), {}, &failure);
        FAIL("expected a division by zero");
    } catch (const interp::EvalError& e) {
        CHECK(std::string(e.what()) == "division by zero");
        CHECK(e.span.line == 3);
        CHECK(e.span.col == 42);
        CHECK(failure.rule == "R");
        CHECK(failure.step == 1);
    }
}

TEST_CASE("a grammar without a limit stops at the default 10 000 steps", "[run][limits]") {
    auto r = derive("node P;\naxiom { p: P at (0, 0); }\nrule Spin { match { p: P; } produce { p; } }\n");
    CHECK(r.run.derivation.steps == interp::kDefaultStepLimit);
    CHECK(r.run.hitDefaultLimit);
}

TEST_CASE("a kept edge moved away from a deleted node survives", "[run][mapping]") {
    // Regression: the edge went with its old end node, and the next deletion hung.
    auto r = derive("node P;\nedge E;\naxiom { a: P at (0, 0); x: P at (1, 0); a -[E]- x; }\nlimit 2;\n"
                    "rule R { match { a: P; x: P where x.age == 0 and a.id < x.id; e: a -[E]- x; }\n"
                    "         produce { n: P at (2, 0); e: a -[E]- n; } }\n"
                    "rule Drop { match { n: P where n.age == 1; } produce { } }\n");
    const auto& g = r.run.graph();
    CHECK(r.run.derivation.steps == 2);
    CHECK(g.nodeCount() == 1);   // a stays; x and then n were deleted
    CHECK(g.edgeCount() == 0);   // e went with n, its new end
}

TEST_CASE("automatic placement on a slanted match scales uniformly, as the thesis's tool", "[run][placement]") {
    // Sketch: a→b drawn (0,0)→(0,5), a node drawn 1 to the right of b; host a→b (0,0)→(1,1).
    auto r = derive("node P;\nedge S directed;\naxiom { a: P at (0, 0); b: P at (1, 1); a -[S]-> b; }\nlimit 1;\n"
                    "rule R { match { a: P @ (0, 0); b: P @ (0, 5); s: a -[S]-> b; } produce { a; b; s; n: P @ (1, 5); } }\n");
    CHECK(r.run.graph().pos(2).x == Approx(1.2));
    CHECK(r.run.graph().pos(2).y == Approx(0.8));
}
