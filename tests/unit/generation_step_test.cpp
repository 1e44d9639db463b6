// `priority P generation;`: every rule of the priority rewrites all its
// matches in one step (ParallelStep::runGeneration), earlier rules claiming
// first. The interpreter here; examples.compiled.sierpinski_arrowhead runs
// both back ends on the arrowhead.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "test_helpers.hpp"

using namespace g2d;

namespace {

std::string arrowhead(const std::string& mode) {
    std::ifstream in(std::string(G2D_SOURCE_DIR) + "/examples/sierpinski_arrowhead.g2d");
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    const std::string generation = "\npriority 0 generation;";   // the declaration, not the comment
    const auto at = s.find(generation);
    REQUIRE(at != std::string::npos);
    return s.replace(at, generation.size(), "\n" + mode);
}

test::SnippetRun run(const std::string& source, long long steps, std::uint64_t seed = 1) {
    return test::runSnippet(source, seed, test::verified(steps));
}

}  // namespace

TEST_CASE("a generation rewrites every rule's matches in one step, as an L-system", "[generation]") {
    for (int g = 1; g <= 6; ++g) {
        INFO("generation " << g);
        const auto r = run(arrowhead("priority 0 generation;"), g);
        CHECK(r.derivation.steps == g);
        const rt::Graph& graph = r.graph();
        // A → B A B, B → A B A: counts (a, b) → (a + 2b, 2a + b), from (1, 0).
        long long a = 1, b = 0;
        for (int k = 0; k < g; ++k) {
            const long long na = a + 2 * b, nb = 2 * a + b;
            a = na;
            b = nb;
        }
        long long seenA = 0, seenB = 0;
        const int kindA = static_cast<int>(r.state().program().kinds.size()) - 2;   // P, A, B: A is the second last
        for (rt::EdgeId e = 0; e < graph.edgeCapacity(); ++e) {
            if (!graph.edgeAlive(e)) continue;
            (graph.edgeKind(e) == kindA ? seenA : seenB)++;
            const double length = rt::distance(graph.pos(graph.source(e)), graph.pos(graph.target(e)));
            CHECK(std::abs(length - std::ldexp(1.0, -g)) < 1e-12);
        }
        CHECK(seenA == a);
        CHECK(seenB == b);
        CHECK(r.derivation.applications == (std::llround(std::pow(3, g)) - 1) / 2);   // 1 + 3 + … + 3^(g-1)
    }
}

TEST_CASE("without `generation`, a parallel step rewrites one rule's matches", "[generation]") {
    // The same grammar with `parallel`: generation 5 (3^5 edges, all of one
    // generation) takes more than 5 steps; each step rewrites one rule's matches.
    const auto r = run(arrowhead("priority 0 parallel;"), 5);
    CHECK(r.derivation.steps == 5);
    CHECK(r.graph().edgeCount() < 243);
}

TEST_CASE("in a generation, earlier rules claim overlapping matches first", "[generation]") {
    const std::string kinds = "node P { v: int = 0; }\naxiom { a: P; b: P at (1, 0); c: P at (2, 0); }\npriority 0 generation;\n";
    const std::string first = "rule First { match { x: P where x.v == 0; } produce { x { v = 1 }; } }\n";
    const std::string second = "rule Second { match { x: P where x.v == 0; } produce { x { v = 2 }; } }\n";
    for (const auto& [source, expected] : {std::pair{kinds + first + second, 1LL}, std::pair{kinds + second + first, 2LL}}) {
        const auto r = run(source, 1);
        CHECK(r.derivation.steps == 1);
        CHECK(r.derivation.applications == 3);
        for (rt::NodeId n : r.graph().allNodes())
            CHECK(std::get<long long>(r.grammar->attribute(rt::ElemClass::Node, n, 0)) == expected);
    }
}

TEST_CASE("a generation step counts once toward its priority's limit, then lower priorities run", "[generation]") {
    const std::string source = R"(
node P { v: int = 0; }
node Q;
axiom { a: P; b: P at (1, 0); }
priority 0 limit 2 generation;
rule Up { match { x: P; } produce { x { v = x.v + 1 }; } }
rule Mark priority 1 { match { x: P where x.v == 2; } produce { x; q: Q at x.pos; } }
limit 4;
)";
    const auto r = run(source, 4);
    CHECK(r.derivation.steps == 4);                 // 2 generations, then Mark twice
    CHECK(r.derivation.applications == 2 * 2 + 2);
    CHECK(r.graph().nodeCount() == 4);
}
