// g2d infer's grammar writer: the two sides of every inferred rule as plain
// graphs (one interface, the same half-edge at each interface node before
// and after, every vertex with its primitive's star), and the `.g2d` text.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "infer/example_json.hpp"
#include "infer/grammar_writer.hpp"
#include "infer/rule_sides.hpp"
#include "infer_examples.hpp"

using namespace g2d::infer;

namespace {

using g2d::test::readFile;
const std::string kExamples = g2d::test::kMerrellExamples;
std::vector<std::pair<std::string, LabelledExample>> allExamples() { return g2d::test::merrellExamples(); }
InferOptions small() { return g2d::test::smallHierarchy(); }

// Per interface node: its edge ends on one side, as (label, 1 if the node is the source).
std::map<int, std::vector<std::pair<int, int>>> interfaceEnds(const RuleSide& side) {
    std::map<int, std::vector<std::pair<int, int>>> ends;
    for (const SideEdge& e : side.edges) {
        if (e.from < 0) ends[-1 - e.from].push_back({e.label, 1});
        if (e.to < 0) ends[-1 - e.to].push_back({e.label, 0});
    }
    return ends;
}

// Every vertex of the side holds exactly its primitive's half-edges.
bool starsMatch(const LabelledExample& ex, const RuleSide& side) {
    std::vector<std::vector<int>> halves(side.primitive.size());
    for (const SideEdge& e : side.edges) {
        if (e.from >= static_cast<int>(halves.size()) || e.to >= static_cast<int>(halves.size())) return false;
        if (e.from >= 0) halves[static_cast<std::size_t>(e.from)].push_back(halfLabel(e.label, false));
        if (e.to >= 0) halves[static_cast<std::size_t>(e.to)].push_back(halfLabel(e.label, true));
    }
    for (std::size_t v = 0; v < halves.size(); ++v) {
        std::vector<int> want = ex.primitives[static_cast<std::size_t>(side.primitive[v])].halves;
        std::sort(want.begin(), want.end());
        std::sort(halves[v].begin(), halves[v].end());
        if (halves[v] != want) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("every rule's sides share one interface, each node with the same half-edge on both", "[infer][writer]") {
    int rules = 0, edgePieces = 0;
    for (const auto& [path, ex] : allExamples()) {
        const InferredGrammar g = inferGrammar(ex, small());
        for (std::size_t r = 0; r < g.rules.size(); ++r) {
            INFO(path << ", rule " << r);
            const InferredRule& rule = g.rules[r];
            const RuleSides s = ruleSides(ex, g, rule);
            ++rules;
            for (const RulePiece& p : rule.right) edgePieces += g.hierarchy[static_cast<std::size_t>(p.graph)].graph.isEdgeGraph() ? 1 : 0;
            CHECK(s.interface == static_cast<int>(g.hierarchy[static_cast<std::size_t>(rule.left)].graph.boundary.size()));
            CHECK((s.interface == 0) == rule.starter());
            if (rule.starter()) CHECK((s.right.primitive.empty() && s.right.edges.empty()));
            const auto left = interfaceEnds(s.left), right = interfaceEnds(s.right);
            CHECK(static_cast<int>(left.size()) == s.interface);
            CHECK(static_cast<int>(right.size()) == s.interface);
            for (int k = 0; k < s.interface; ++k) {
                INFO("interface node " << k);
                REQUIRE(left.count(k) == 1);
                REQUIRE(right.count(k) == 1);
                CHECK(left.at(k).size() == 1);
                CHECK(left.at(k) == right.at(k));
            }
            CHECK(starsMatch(ex, s.left));
            CHECK(starsMatch(ex, s.right));
        }
    }
    CHECK(rules > 1000);
    CHECK(edgePieces > 0);   // the edge-graph case (two interface nodes joined) is exercised
}

TEST_CASE("the triangle's grammar text", "[infer][writer]") {
    const std::string path = kExamples + "/2D Basic Shapes/triangle.json";
    const LabelledExample ex = labelExample(readExampleJson(readFile(path), path));
    // Vertices (2.5, -5), (5, -2.5), (7.5, -5): a box 5 x 2.5, its height grown to the median edge,
    // 3.54, so 3 vertices in 17.7 square units; 20 x 3 vertices by default, 10 x 60 = 600 steps
    // raised to 1000; edges 3.54, 3.54 and 5 long: half the shortest to twice the longest, strokes 0.05 x 3.54;
    // starters weigh 1 (Merrell's proposal mix).
    const std::string golden = R"(// Inferred by `g2d infer` from triangle.json (Merrell 2023, example-based graph grammars).
// 3 edge labels, 3 primitives, 0 rules, 1 starters. Run: g2d run <file> -o out.svg --seed 1

// Size and space (-D NAME=VALUE): the cost steers the walk toward target_vertices;
// the canvas holds that many at the example's density (0.169706 vertices per unit area)
// with room to spare, unless canvas_width and canvas_height say otherwise.
param target_vertices: int = 60;   // the example has 3
param canvas_width: float = 0;    // 0: sized for target_vertices
param canvas_height: float = 0;
param iterations: int = 1000;
const room: float = 2.25 * target_vertices / 0.169706;
const width: float = canvas_width > 0 ? canvas_width : sqrt(room * 1.41421);
const height: float = canvas_height > 0 ? canvas_height : sqrt(room / 1.41421);
canvas (0, 0) to (width, height);
limit iterations;

// The drawing step (Merrell §6.2) and Metropolis acceptance (§6.3): a proposal that
// raises the cost by d is accepted with probability exp(-d / temperature). Add terms
// to steer the output, e.g. `- 0.5 * count(P0)` for more vertices of primitive P0.
layout angles {
    cost = 0.5 * abs(nodes - target_vertices);
    temperature = 1;
    clearance = 0.071;
}

// Edge labels: brush, the areas left and right, the direction.
edge E0 directed {
    label: int = 0;
    layout { angle = radians(45); min_length = 1.767767; max_length = 10; }
    style { stroke = "#202020"; stroke_width = 0.18; }
}
edge E1 directed {
    label: int = 1;
    layout { angle = radians(135); min_length = 1.767767; max_length = 10; }
    style { stroke = "#202020"; stroke_width = 0.18; }
}
edge E2 directed {
    label: int = 2;
    layout { angle = radians(0); min_length = 1.767767; max_length = 10; }
    style { stroke = "#202020"; stroke_width = 0.18; }
}

// Primitives (vertex stars): the half-edges counter-clockwise.
node P0 { style { tag = "none"; } }   // E2 out 0°, E0 out 45°
node P1 { style { tag = "none"; } }   // E0 in 225°, E1 in 315°
node P2 { style { tag = "none"; } }   // E1 out 135°, E2 in 180°

axiom { }

// Starter 0: a complete graph from nothing, and back to nothing.
rule Start0 dpo weight 1 {
    match { }
    produce {
        v0: P0;
        v1: P2;
        v2: P1;
        v0 -[E2]-> v1;
        v0 -[E0]-> v2;
        v1 -[E1]-> v2;
    }
}
rule Stop0 dpo weight 1 {
    match {
        v0: P0;
        v1: P2;
        v2: P1;
        v0 -[E2]-> v1;
        v0 -[E0]-> v2;
        v1 -[E1]-> v2;
    }
    produce { }
}
)";
    WriterOptions o;
    o.source = "triangle.json";
    CHECK(writeGrammar(ex, inferGrammar(ex), o) == golden);
}

TEST_CASE("the grammar text is deterministic, with two rules per inferred rule", "[infer][writer]") {
    for (const auto& [path, ex] : allExamples()) {
        INFO(path);
        WriterOptions o;
        o.source = path;
        o.iterations = 500;
        const InferredGrammar g = inferGrammar(ex, small());
        const std::string text = writeGrammar(ex, g, o);
        CHECK(text == writeGrammar(ex, inferGrammar(ex, small()), o));
        CHECK(text.find("param iterations: int = 500;\n") != std::string::npos);
        std::size_t rules = 0;
        for (std::size_t at = text.find("\nrule "); at != std::string::npos; at = text.find("\nrule ", at + 1)) ++rules;
        CHECK(rules == 2 * g.rules.size());
    }
}
