// The lowered rewrite programs (compiler/lower): what both back ends execute
// or print, checked as text.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "lower/match_program.hpp"
#include "lower/rewrite_program.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

std::string lowered(const std::string& source, std::size_t rule = 0, std::size_t daughter = 0) {
    auto c = test::compile(source);
    INFO(test::firstError(c));
    REQUIRE(c.program);
    const ir::Rule& r = c.program->rules.at(rule);
    return lower::printRewrite(*c.program, r, lower::lowerRewrite(*c.program, r, daughter));
}

std::string example(const std::string& name) {
    std::ifstream in(std::string(G2D_SOURCE_DIR) + "/examples/" + name);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST_CASE("the Koch split, lowered", "[lower]") {
    // Values first, in the order written (lets, then each new node's
    // position); then the edge goes, the nodes come, the edges are made.
    CHECK(lowered(example("koch_snowflake.g2d")) ==
          "prepare\n"
          "  let L0 <- expr 43:13\n"
          "  let L1 <- expr 44:13\n"
          "  let L2 <- expr 45:15\n"
          "  r0 <- finite position 48:21\n"
          "  r1 <- finite position 49:21\n"
          "  r2 <- finite position 50:21\n"
          "  r3 <- expr 51:25\n"
          "  r4 <- expr 52:25\n"
          "  r5 <- expr 53:25\n"
          "  r6 <- expr 54:25\n"
          "commit\n"
          "  delete edge old\n"
          "  h0 = s\n"
          "  h1 = e\n"
          "  h2 = new Point at r0\n"
          "  h3 = new Point at r1\n"
          "  h4 = new Point at r2\n"
          "  k0 = new Seg h0 -> h2 {lod = r3}\n"
          "  k1 = new Seg h2 -> h3 {lod = r4}\n"
          "  k2 = new Seg h3 -> h4 {lod = r5}\n"
          "  k3 = new Seg h4 -> h1 {lod = r6}\n"
          "writes old\n");
}

TEST_CASE("kept elements: moves, rewiring, attribute writes recorded once, literals as they are", "[lower]") {
    const std::string src = test::prelude() +
                            "node Q;\n"
                            "rule R {\n"
                            "    match { a: P @ (0, 0); b: P @ (1, 0); x: a -[E]-> b; u: a -[U]- b; }\n"
                            "    produce {\n"
                            "        a at a.pos + (1, 0) { w = 2.5 };\n"
                            "        b { style.fill = \"red\" };\n"
                            "        q: Q @ (0, 1);\n"
                            "        x: b -[E { n = x.n + 1 }]-> a;\n"
                            "        q -[U]- a;\n"
                            "    }\n"
                            "}\n";
    CHECK(lowered(src) ==
          "prepare\n"
          "  place h2@(0, 1)\n"
          "  r0 <- finite position 9:14\n"
          "  r1 <- placed h2\n"
          "  r2 <- expr 12:24\n"
          "commit\n"
          "  delete edge u\n"
          "  h0 = a\n"
          "  h1 = b\n"
          "  h2 = new Q at r1\n"
          "  rewire x h1 -> h0\n"
          "  h0.pos = r0\n"
          "  h0.w = 2.5\n"
          "  touch values h0\n"
          "  h1.style.fill = \"red\"\n"
          "  k0 = x\n"
          "  k0.n = r2\n"
          "  touch edge k0\n"
          "  k1 = new U h2 -> h0\n"
          "writes a b u x\n");
}

TEST_CASE("match lists carry every decision: kinds, distinct slots, order, the new-edge gate", "[lower]") {
    const std::string src = "node P; node Q;\nedge E directed;\nedge F;\n"
                            "axiom { a: P at (0, 0); b: P at (1, 0); a -[E]-> b; }\n"
                            "rule R ordered {\n"
                            "    match { a: P @ (0, 0); b: P @ (1, 1); x: a -[E]-> b; not { q: Q; b -[E]-> q; } }\n"
                            "    produce { a; b; x; }\n"
                            "}\n";
    auto c = test::compile(src);
    INFO(test::firstError(c));
    REQUIRE(c.program);
    const lower::MatchProgram m = lower::lowerMatch(*c.program, c.program->rules.at(0));
    REQUIRE(m.full.size() == 2);
    const auto& scan = std::get<lower::ScanNodes>(m.full[0]);
    CHECK(scan.node == 0);
    CHECK(scan.distinctNodes.empty());
    CHECK(scan.edgeKinds != 0);   // a needs an E edge
    const auto& extend = std::get<lower::ExtendEdge>(m.full[1]);
    CHECK((extend.from == 0 && extend.node == 1 && extend.directed && extend.fromIsSource));
    CHECK(extend.distinctNodes == std::vector<int>{0});
    CHECK(extend.newEdgeGate);    // the pattern's only edge
    // b is drawn right of and above a: its host must be neither left of nor below a's.
    REQUIRE(extend.ordered.size() == 2);
    CHECK((extend.ordered[0].other == 0 && extend.ordered[0].axis == 0 && !extend.ordered[0].before));
    CHECK((extend.ordered[1].other == 0 && extend.ordered[1].axis == 1 && !extend.ordered[1].before));
    // The negative condition: its slots after the pattern's, no gate, no order, no edge-kind pretest.
    REQUIRE(m.negatives.size() == 1);
    const auto& nac = std::get<lower::ExtendEdge>(m.negatives[0][0]);
    CHECK((nac.from == 1 && nac.node == 2 && nac.edge == 1));
    CHECK(nac.distinctNodes == std::vector<int>{0, 1});
    CHECK(nac.distinctEdges == std::vector<int>{0});
    CHECK_FALSE(nac.newEdgeGate);
    CHECK(nac.ordered.empty());
    CHECK(m.anchored.size() == 2);
    CHECK(m.nodeSlots == 3);
    CHECK(m.edgeSlots == 2);
}
