// `layout angles` (Merrell 2023's drawing step) through the interpreter:
// every application is drawn before it is committed (edges along their
// kinds' angles, lengths in range, nodes in the canvas, the drawing
// planar); a rejected drawing changes nothing and still counts as a step;
// after the run the drawing's bounded faces become faces of the kinds the
// edge kinds name on their sides. Checked independently of the solver: the
// expected directions are written out here, not read from the program.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "g2d/json_writer.hpp"
#include "interp/drawing.hpp"
#include "interp/run_program.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

constexpr double kTol = 1e-9;
constexpr double kPi = std::numbers::pi;

struct Run {
    CompileResult compiled;
    interp::RunResult run;
};

// Compiles and runs `source` with match verification on (test::verified()).
Run derive(const std::string& source, std::uint64_t seed = 1, const rt::StepObserver& observer = {}) {
    Run r{test::compile(source), {}};
    INFO(test::firstError(r.compiled));
    REQUIRE(r.compiled.program);
    r.run = interp::runProgram(*r.compiled.program, interp::defaultParams(*r.compiled.program), seed, test::verified(),
                               observer);
    return r;
}

int kindIndex(const ir::Program& p, const std::string& name) {
    for (std::size_t i = 0; i < p.kinds.size(); ++i)
        if (p.kinds[i].name == name) return static_cast<int>(i);
    return -1;
}

// An edge kind's expected geometry, written out by each test.
struct Geometry {
    double angle, minLength, maxLength;
};
using Geometries = std::map<std::string, Geometry>;

const Geometries kUnitSides{{"R", {0, 1, 1}}, {"U", {kPi / 2, 1, 1}}, {"L", {kPi, 1, 1}}, {"D", {3 * kPi / 2, 1, 1}}};

// Unit squares made from nothing: a (low left) -R-> b -U-> c -L-> d -D-> a,
// counter-clockwise. `sides[k]` is written into kind k's layout (R, U, L, D).
std::string squareGrammar(const std::string& canvasMax, int limit,
                          const std::array<std::string, 4>& sides = {"left = Cell;", "left = Cell;", "left = Cell;",
                                                                     "left = Cell;"},
                          const std::string& extraKinds = "") {
    return "layout angles { canvas_min = (0, 0); canvas_max = " + canvasMax + "; }\n"
           "face Cell;\n" + extraKinds +
           "node Corner;\n"
           "edge R directed { layout { angle = 0; length = 1; " + sides[0] + " } }\n"
           "edge U directed { layout { angle = radians(90); length = 1; " + sides[1] + " } }\n"
           "edge L directed { layout { angle = radians(180); length = 1; " + sides[2] + " } }\n"
           "edge D directed { layout { angle = radians(270); length = 1; " + sides[3] + " } }\n"
           "axiom { }\n"
           "limit " + std::to_string(limit) + ";\n"
           "rule Square {\n"
           "    match { }\n"
           "    produce { a: Corner; b: Corner; c: Corner; d: Corner; a -[R]-> b; b -[U]-> c; c -[L]-> d; d -[D]-> a; }\n"
           "}\n";
}

double cross(rt::vec2 o, rt::vec2 a, rt::vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool inBox(rt::vec2 a, rt::vec2 b, rt::vec2 p) {
    return p.x >= std::min(a.x, b.x) - kTol && p.x <= std::max(a.x, b.x) + kTol && p.y >= std::min(a.y, b.y) - kTol &&
           p.y <= std::max(a.y, b.y) + kTol;
}

// Whether the closed segments ab and cd have a point in common.
bool segmentsMeet(rt::vec2 a, rt::vec2 b, rt::vec2 c, rt::vec2 d) {
    const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
    auto opposite = [](double u, double v) { return (u > kTol && v < -kTol) || (u < -kTol && v > kTol); };
    if (opposite(d1, d2) && opposite(d3, d4)) return true;
    return (std::abs(d1) <= kTol && inBox(c, d, a)) || (std::abs(d2) <= kTol && inBox(c, d, b)) ||
           (std::abs(d3) <= kTol && inBox(a, b, c)) || (std::abs(d4) <= kTol && inBox(a, b, d));
}

std::vector<rt::EdgeId> liveEdges(const rt::Graph& g) {
    std::vector<rt::EdgeId> out;
    for (rt::EdgeId e = 0; e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) out.push_back(e);
    return out;
}

// Every edge along its kind's angle with a length in range, every node in
// the canvas, and no two edges without a common end touching.
void checkDrawing(const rt::Graph& g, const ir::Program& prog, const Geometries& kinds, rt::vec2 lo, rt::vec2 hi) {
    const std::vector<rt::EdgeId> edges = liveEdges(g);
    for (rt::EdgeId e : edges) {
        const std::string& kind = prog.kinds[static_cast<std::size_t>(g.edgeKind(e))].name;
        INFO("edge " << e << " of kind " << kind);
        REQUIRE(kinds.count(kind) == 1);
        const Geometry& k = kinds.at(kind);
        const rt::vec2 v = g.pos(g.target(e)) - g.pos(g.source(e));
        const double length = std::hypot(v.x, v.y);
        CHECK(length >= k.minLength - kTol);
        CHECK(length <= k.maxLength + kTol);
        CHECK(std::abs(v.x - length * std::cos(k.angle)) <= kTol);
        CHECK(std::abs(v.y - length * std::sin(k.angle)) <= kTol);
    }
    for (rt::NodeId n : g.allNodes()) {
        INFO("node " << n << " at (" << g.pos(n).x << ", " << g.pos(n).y << ")");
        CHECK(g.pos(n).x >= lo.x - kTol);
        CHECK(g.pos(n).y >= lo.y - kTol);
        CHECK(g.pos(n).x <= hi.x + kTol);
        CHECK(g.pos(n).y <= hi.y + kTol);
    }
    int crossings = 0;
    for (std::size_t i = 0; i < edges.size(); ++i)
        for (std::size_t j = i + 1; j < edges.size(); ++j) {
            const rt::EdgeId e = edges[i], f = edges[j];
            if (g.source(e) == g.source(f) || g.source(e) == g.target(f) || g.target(e) == g.source(f) ||
                g.target(e) == g.target(f))
                continue;
            if (segmentsMeet(g.pos(g.source(e)), g.pos(g.target(e)), g.pos(g.source(f)), g.pos(g.target(f)))) ++crossings;
        }
    CHECK(crossings == 0);
}

std::vector<rt::NodeId> cornersOf(const rt::Graph& g, rt::FaceId f) {
    std::vector<rt::NodeId> out;
    const rt::CornerId first = g.firstCorner(f);
    rt::CornerId c = first;
    do {
        out.push_back(g.cornerNode(c));
        c = g.nextCorner(c);
    } while (c != first);
    return out;
}

double signedArea(const rt::Graph& g, const std::vector<rt::NodeId>& corners) {
    double a = 0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const rt::vec2 u = g.pos(corners[i]), v = g.pos(corners[(i + 1) % corners.size()]);
        a += u.x * v.y - u.y * v.x;
    }
    return a / 2;
}

std::vector<rt::FaceId> liveFaces(const rt::Graph& g) {
    std::vector<rt::FaceId> out;
    for (rt::FaceId f = 0; f < g.faceCapacity(); ++f)
        if (g.faceAlive(f)) out.push_back(f);
    return out;
}

std::set<std::pair<rt::NodeId, rt::NodeId>> directedPairs(const rt::Graph& g) {
    std::set<std::pair<rt::NodeId, rt::NodeId>> out;
    for (rt::EdgeId e : liveEdges(g)) out.insert({g.source(e), g.target(e)});
    return out;
}

// Every face is a unit square of kind `kind`, counter-clockwise, whose sides
// are edges (forward: u -> v for consecutive corners u, v; else v -> u); the
// faces' corners are all the nodes, each once.
void checkUnitSquareFaces(const rt::Graph& g, int kind, bool forward) {
    const auto pairs = directedPairs(g);
    std::set<rt::NodeId> seen;
    for (rt::FaceId f : liveFaces(g)) {
        INFO("face " << f);
        CHECK(g.faceKind(f) == kind);
        const auto corners = cornersOf(g, f);
        REQUIRE(corners.size() == 4);
        CHECK(std::abs(signedArea(g, corners) - 1.0) <= kTol);
        for (std::size_t i = 0; i < 4; ++i) {
            const rt::NodeId u = corners[i], v = corners[(i + 1) % 4];
            CHECK(pairs.count(forward ? std::make_pair(u, v) : std::make_pair(v, u)) == 1);
            CHECK(seen.insert(u).second);
        }
    }
    CHECK(seen.size() == g.nodeCount());
}

// The low left corners of the squares (the sources of R edges).
std::vector<rt::vec2> squareOrigins(const rt::Graph& g, int rKind) {
    std::vector<rt::vec2> out;
    for (rt::EdgeId e : liveEdges(g))
        if (g.edgeKind(e) == rKind) out.push_back(g.pos(g.source(e)));
    return out;
}

int overlappingSquares(const std::vector<rt::vec2>& origins) {
    int overlaps = 0;
    for (std::size_t i = 0; i < origins.size(); ++i)
        for (std::size_t j = i + 1; j < origins.size(); ++j)
            if (std::abs(origins[i].x - origins[j].x) < 1 - kTol && std::abs(origins[i].y - origins[j].y) < 1 - kTol) ++overlaps;
    return overlaps;
}

std::string json(const Run& r, std::uint64_t seed) {
    return rt::writeJson(r.run.graph(), interp::jsonSchema(*r.compiled.program), {{"seed", static_cast<long long>(seed)}});
}

}  // namespace

TEST_CASE("unit squares from an empty match are exact, in the canvas, disjoint, one Cell face each", "[angle-layout]") {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        INFO("seed " << seed);
        auto r = derive(squareGrammar("(10, 10)", 5), seed);
        const auto& prog = *r.compiled.program;
        const auto& d = r.run.derivation;
        const rt::Graph& g = r.run.graph();
        CHECK(d.steps == 5);
        CHECK(d.stopped == rt::StopReason::StepLimit);
        CHECK(d.applications == 5);   // five unit squares fit a 10 x 10 canvas easily
        CHECK(d.rejectedDrawings == 0);
        CHECK(g.nodeCount() == 20);
        CHECK(g.edgeCount() == 20);
        checkDrawing(g, prog, kUnitSides, {0, 0}, {10, 10});
        const auto origins = squareOrigins(g, kindIndex(prog, "R"));
        CHECK(origins.size() == 5);
        CHECK(overlappingSquares(origins) == 0);
        CHECK(g.faceCount() == 5);
        CHECK(g.facesOfKind(kindIndex(prog, "Cell")).size() == 5);
        checkUnitSquareFaces(g, kindIndex(prog, "Cell"), true);
    }
}

TEST_CASE("a rejected drawing changes nothing and still counts as a step", "[angle-layout]") {
    // At most nine unit squares fit a 3 x 3 canvas, so of 30 steps at least
    // 21 are rejected drawings.
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        INFO("seed " << seed);
        std::map<rt::NodeId, rt::vec2> placed;   // every node's position when first seen
        long long observed = 0, grew = 0, moved = 0, oddSteps = 0;
        std::size_t before = 0;
        auto observer = [&](long long step, const rt::Graph& g) {
            ++observed;
            if (step != observed) ++oddSteps;
            const std::size_t now = g.nodeCount();
            if (now == before + 4) ++grew;
            else if (now != before) ++oddSteps;
            before = now;
            for (rt::NodeId n : g.allNodes()) {
                auto [it, fresh] = placed.emplace(n, g.pos(n));
                if (!fresh && (it->second.x != g.pos(n).x || it->second.y != g.pos(n).y)) ++moved;
            }
        };
        auto r = derive(squareGrammar("(3, 3)", 30), seed, observer);
        const auto& d = r.run.derivation;
        const rt::Graph& g = r.run.graph();
        CHECK(d.steps == 30);
        CHECK(observed == 30);
        CHECK(oddSteps == 0);
        CHECK(d.applications + d.rejectedDrawings == 30);
        CHECK(d.rejectedDrawings >= 21);
        CHECK(d.applications >= 1);
        CHECK(grew == d.applications);
        CHECK(moved == 0);   // new squares are separate components: nothing old is freed
        CHECK(g.nodeCount() == static_cast<std::size_t>(4 * d.applications));
        CHECK(g.faceCount() == static_cast<std::size_t>(d.applications));
        checkDrawing(g, *r.compiled.program, kUnitSides, {0, 0}, {3, 3});
        CHECK(overlappingSquares(squareOrigins(g, kindIndex(*r.compiled.program, "R"))) == 0);
    }
}

TEST_CASE("a drawing that never fits the canvas leaves the graph empty", "[angle-layout]") {
    // The sides along x fit (1 long in 1.5), a square (1 high in 0.5) never does.
    auto r = derive(squareGrammar("(1.5, 0.5)", 5));
    const auto& d = r.run.derivation;
    CHECK(d.steps == 5);
    CHECK(d.stopped == rt::StopReason::StepLimit);
    CHECK(d.applications == 0);
    CHECK(d.rejectedDrawings == 5);
    CHECK(r.run.graph().nodeCount() == 0);
    CHECK(r.run.graph().edgeCount() == 0);
    CHECK(r.run.graph().faceCount() == 0);
}

TEST_CASE("a canvas no edge fits in is an error before the first step", "[angle-layout]") {
    const CompileResult compiled = test::compile(squareGrammar("(0.5, 0.5)", 5));
    REQUIRE(compiled.program);
    CHECK_THROWS_WITH(interp::runProgram(*compiled.program, interp::defaultParams(*compiled.program), 1, rt::RunSettings{}),
                      "the canvas, 0.5 x 0.5, is smaller than the shortest edge of every edge kind (the least is 1 long): "
                      "nothing can be drawn in it");
}

TEST_CASE("the same seed gives the same drawing, another seed another", "[angle-layout]") {
    const std::string grammar = squareGrammar("(10, 10)", 6);
    const std::string first = json(derive(grammar, 3), 3);
    CHECK(first == json(derive(grammar, 3), 3));
    CHECK(first != json(derive(grammar, 4), 3));   // the same seed written: only the drawing differs
    CHECK(first.find("\"Cell\"") != std::string::npos);   // the traced faces are in the output
}

TEST_CASE("a face takes the kind most of its sides give it, the outer boundary none", "[angle-layout]") {
    // R, the side of each square's least half-edge, names Door inside: the
    // other three name Cell, so the face is a Cell. (Naming an area outside
    // the squares would keep them from being drawn in the open: areas must
    // agree, areasConsistent.)
    auto r = derive(squareGrammar("(10, 10)", 4,
                                  {"left = Door;", "left = Cell;", "left = Cell;", "left = Cell;"},
                                  "face Door;\n"),
                    2);
    const auto& prog = *r.compiled.program;
    const rt::Graph& g = r.run.graph();
    REQUIRE(r.run.derivation.applications == 4);
    CHECK(g.faceCount() == 4);
    CHECK(g.facesOfKind(kindIndex(prog, "Cell")).size() == 4);
    CHECK(g.facesOfKind(kindIndex(prog, "Door")).empty());
    checkUnitSquareFaces(g, kindIndex(prog, "Cell"), true);
}

TEST_CASE("`right` gives the face on an edge's right: clockwise squares", "[angle-layout]") {
    // a (low left) -U-> b -R-> c -D-> d -L-> a: the inside is on each side's right.
    const std::string grammar =
        "layout angles { canvas_min = (0, 0); canvas_max = (10, 10); }\n"
        "face Cell;\nnode Corner;\n"
        "edge R directed { layout { angle = 0; length = 1; right = Cell; } }\n"
        "edge U directed { layout { angle = radians(90); length = 1; right = Cell; } }\n"
        "edge L directed { layout { angle = radians(180); length = 1; right = Cell; } }\n"
        "edge D directed { layout { angle = radians(270); length = 1; right = Cell; } }\n"
        "axiom { }\nlimit 4;\n"
        "rule Square { match { } produce { a: Corner; b: Corner; c: Corner; d: Corner; "
        "a -[U]-> b; b -[R]-> c; c -[D]-> d; d -[L]-> a; } }\n";
    auto r = derive(grammar, 5);
    const auto& prog = *r.compiled.program;
    const rt::Graph& g = r.run.graph();
    REQUIRE(r.run.derivation.applications == 4);
    checkDrawing(g, prog, kUnitSides, {0, 0}, {10, 10});
    CHECK(g.faceCount() == 4);
    checkUnitSquareFaces(g, kindIndex(prog, "Cell"), false);   // counter-clockwise, against the edges
}

TEST_CASE("edges with a length range: in range, sampled, rectangles closed", "[angle-layout]") {
    const std::string grammar =
        "layout angles { canvas_min = (-5, -5); canvas_max = (15, 15); proposals = 3; samples = 20; }\n"
        "face Cell;\nnode Corner;\n"
        "edge H directed { layout { angle = 0; min_length = 1; max_length = 2; left = Cell; } }\n"
        "edge Ht directed { layout { angle = 0; min_length = 1; max_length = 2; right = Cell; } }\n"
        "edge V directed { layout { angle = radians(90); min_length = 0.5; max_length = 1.5; left = Cell; } }\n"
        "edge Vl directed { layout { angle = radians(90); min_length = 0.5; max_length = 1.5; right = Cell; } }\n"
        "axiom { }\nlimit 6;\n"
        "rule Box { match { } produce { a: Corner; b: Corner; c: Corner; d: Corner; "
        "a -[H]-> b; b -[V]-> c; d -[Ht]-> c; a -[Vl]-> d; } }\n";
    auto r = derive(grammar, 7);
    const auto& prog = *r.compiled.program;
    const rt::Graph& g = r.run.graph();
    REQUIRE(r.run.derivation.applications == 6);
    checkDrawing(g, prog, {{"H", {0, 1, 2}}, {"Ht", {0, 1, 2}}, {"V", {kPi / 2, 0.5, 1.5}}, {"Vl", {kPi / 2, 0.5, 1.5}}}, {-5, -5}, {15, 15});
    std::set<double> widths, heights;
    for (rt::EdgeId e : liveEdges(g)) {
        const rt::vec2 v = g.pos(g.target(e)) - g.pos(g.source(e));
        const int k = g.edgeKind(e);
        (k == kindIndex(prog, "H") || k == kindIndex(prog, "Ht") ? widths : heights).insert(std::hypot(v.x, v.y));
    }
    // Each rectangle's opposite sides are equal; the six rectangles differ
    // (lengths are sampled within the range, not fixed at its ends).
    CHECK(widths.size() >= 2);
    CHECK(heights.size() >= 2);
    CHECK(g.faceCount() == 6);
    for (rt::FaceId f : liveFaces(g)) {
        CHECK(g.faceKind(f) == kindIndex(prog, "Cell"));
        const auto corners = cornersOf(g, f);
        CHECK(corners.size() == 4);
        CHECK(signedArea(g, corners) >= 0.5 - kTol);   // counter-clockwise, at least 1 x 0.5
    }
}

TEST_CASE("a chain grown from kept nodes stays straight when old nodes are freed", "[angle-layout]") {
    // A chain of 30 nodes with sides of 0.5 or more needs 14.5: it cannot
    // fit in a canvas 10 wide, so the growth ends in rejected drawings.
    const std::string grammar =
        "layout angles { canvas_min = (0, 0); canvas_max = (10, 2); }\n"
        "node Dot;\n"
        "edge R directed { layout { angle = 0; min_length = 0.5; max_length = 1; } }\n"
        "axiom { }\nlimit 30;\n"
        "rule Seed { match { not { x: Dot; } } produce { a: Dot; } }\n"
        "rule Grow { match { a: Dot; not { b: Dot; a -[R]-> b; } } produce { a; b: Dot; a -[R]-> b; } }\n";
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        INFO("seed " << seed);
        auto r = derive(grammar, seed);
        const auto& d = r.run.derivation;
        const rt::Graph& g = r.run.graph();
        CHECK(d.steps == 30);
        CHECK(d.applications + d.rejectedDrawings == 30);
        CHECK(d.rejectedDrawings >= 9);
        CHECK(g.nodeCount() == static_cast<std::size_t>(d.applications));
        CHECK(g.edgeCount() + 1 == g.nodeCount());
        checkDrawing(g, *r.compiled.program, {{"R", {0, 0.5, 1}}}, {0, 0}, {10, 2});
        const double y = g.pos(*g.allNodes().begin()).y;
        for (rt::NodeId n : g.allNodes()) CHECK(std::abs(g.pos(n).y - y) <= kTol);
        CHECK(g.faceCount() == 0);   // no kind names a face
    }
}

TEST_CASE("squares made and unmade by dpo rules keep a valid drawing and its faces", "[angle-layout]") {
    std::string grammar = squareGrammar("(6, 6)", 60);
    grammar.replace(grammar.find("rule Square {"), 13, "rule Square dpo {");
    grammar +=
        "rule Unmake dpo {\n"
        "    match { a: Corner; b: Corner; c: Corner; d: Corner; a -[R]-> b; b -[U]-> c; c -[L]-> d; d -[D]-> a; }\n"
        "    produce { }\n"
        "}\n";
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        INFO("seed " << seed);
        auto r = derive(grammar, seed);
        const auto& prog = *r.compiled.program;
        const auto& d = r.run.derivation;
        const rt::Graph& g = r.run.graph();
        CHECK(d.steps == 60);
        CHECK(d.applications + d.rejectedDrawings == 60);
        CHECK(g.nodeCount() % 4 == 0);
        CHECK(g.nodeCount() < static_cast<std::size_t>(4 * d.applications));   // some squares were unmade
        checkDrawing(g, prog, kUnitSides, {0, 0}, {6, 6});
        CHECK(overlappingSquares(squareOrigins(g, kindIndex(prog, "R"))) == 0);
        CHECK(g.faceCount() == g.nodeCount() / 4);
        checkUnitSquareFaces(g, kindIndex(prog, "Cell"), true);
    }
}

TEST_CASE("layout values may be constants and built-ins", "[angle-layout]") {
    const std::string grammar =
        "const side: float = 2;\n"
        "const turn = 90;\n"
        "layout angles { canvas_min = (0, 0); canvas_max = (side * 5, side * 5); samples = 1 + 4; }\n"
        "node Dot;\n"
        "edge Up directed { layout { angle = radians(turn); length = side; } }\n"
        "axiom { }\nlimit 3;\n"
        "rule Stick { match { } produce { a: Dot; b: Dot; a -[Up]-> b; } }\n";
    auto r = derive(grammar, 1);
    REQUIRE(r.run.derivation.applications == 3);
    checkDrawing(r.run.graph(), *r.compiled.program, {{"Up", {kPi / 2, 2, 2}}}, {0, 0}, {10, 10});
}

TEST_CASE("a layout without `layout angles` is a warning and changes nothing", "[angle-layout]") {
    const std::string grammar =
        "node Dot;\n"
        "edge Up directed { layout { angle = radians(90); length = 1; } }\n"
        "axiom { a: Dot at (0, 0); }\nlimit 2;\n"
        "rule Grow { match { a: Dot; } produce { a; b: Dot at (a.pos.x + 3, 7); a -[Up]-> b; } }\n";
    const auto compiled = test::compile(grammar);
    REQUIRE(compiled.program);
    CHECK(test::firstError(compiled).empty());
    CHECK(test::diagnosticLines(compiled) ==
          std::vector<std::string>{"2:6: warning: edge kind `Up` has a layout, but the grammar has no `layout angles { … }` "
                                   "that uses it"});
    auto r = derive(grammar, 1);
    CHECK(r.run.derivation.applications == 2);
    CHECK(r.run.derivation.rejectedDrawings == 0);
    for (rt::NodeId n : r.run.graph().allNodes())
        if (n != 0) CHECK(r.run.graph().pos(n).y == 7.0);   // placed by `at`, not drawn
    CHECK(r.run.graph().faceCount() == 0);
}

TEST_CASE("an edge kind with a unit is drawn only at whole multiples of it, freed edges too", "[angle-layout]") {
    // Rectangles whose sides are whole multiples of 0.5 between 0.5 and 3,
    // and a bridge of whole units between two of them, drawn level by
    // freeing corners (whose sides then stretch, still by whole halves).
    const std::string grammar = R"(
canvas (0, 0) to (14, 14);
node Corner { style { tag = "none"; } }
layout angles { }
edge R directed { layout { angle = 0; min_length = 0.5; max_length = 3; unit = 0.5; } }
edge U directed { layout { angle = radians(90); min_length = 0.5; max_length = 3; unit = 0.5; } }
edge L directed { layout { angle = radians(180); min_length = 0.5; max_length = 3; unit = 0.5; } }
edge D directed { layout { angle = radians(270); min_length = 0.5; max_length = 3; unit = 0.5; } }
edge Bridge directed { layout { angle = 0; min_length = 1; max_length = 4; unit = 1; } }
axiom { }
limit 300;
rule Square dpo weight 1 {
    match { }
    produce { a: Corner; b: Corner; c: Corner; d: Corner; a -[R]-> b; b -[U]-> c; c -[L]-> d; d -[D]-> a; }
}
rule Join dpo weight 4 {
    match { x: Corner; p: Corner; q: Corner; z: Corner; e: x -[R]-> p; f: q -[R]-> z; where distance(p.pos, q.pos) <= 4; not { p -[Bridge]-> q; } }
    produce { x; p; q; z; e; f; p -[Bridge]-> q; }
}
)";
    int bridges = 0, sides = 0;
    for (std::uint64_t seed : {1, 2, 3}) {
        const auto r = derive(grammar, seed);
        const rt::Graph& g = r.run.graph();
        for (rt::EdgeId e : liveEdges(g)) {
            const bool bridge = r.compiled.program->kinds[static_cast<std::size_t>(g.edgeKind(e))].name == "Bridge";
            const rt::vec2 v = g.pos(g.target(e)) - g.pos(g.source(e));
            const double k = std::hypot(v.x, v.y) / (bridge ? 1.0 : 0.5);
            INFO("edge " << e << (bridge ? " (a bridge)" : "") << ": " << k << " units");
            CHECK(std::abs(k - std::round(k)) < 1e-9);
            (bridge ? bridges : sides)++;
        }
    }
    CHECK(bridges > 0);
    CHECK(sides > 0);
}

TEST_CASE("clearance keeps every node that far from the edges not at it", "[angle-layout]") {
    // Unit squares placed anywhere in a small canvas: without a clearance
    // they may come within a hair of each other.
    const std::string grammar = R"(
canvas (0, 0) to (6, 6);
layout angles { clearance = 0.4; }
node Corner { style { tag = "none"; } }
edge R directed { layout { angle = 0; length = 1; } }
edge U directed { layout { angle = radians(90); length = 1; } }
edge L directed { layout { angle = radians(180); length = 1; } }
edge D directed { layout { angle = radians(270); length = 1; } }
axiom { }
limit 60;
rule Square dpo {
    match { }
    produce { a: Corner; b: Corner; c: Corner; d: Corner; a -[R]-> b; b -[U]-> c; c -[L]-> d; d -[D]-> a; }
}
)";
    auto near = [](rt::vec2 p, rt::vec2 a, rt::vec2 b) {
        const rt::vec2 ab = b - a, ap = p - a;
        const double t = std::clamp((ap.x * ab.x + ap.y * ab.y) / (ab.x * ab.x + ab.y * ab.y), 0.0, 1.0);
        return std::hypot(ap.x - t * ab.x, ap.y - t * ab.y);
    };
    int squares = 0;
    for (std::uint64_t seed : {1, 2, 3}) {
        const auto r = derive(grammar, seed);
        const rt::Graph& g = r.run.graph();
        squares += static_cast<int>(g.nodeCount() / 4);
        double least = 1e9;
        for (rt::NodeId n : g.allNodes())
            for (rt::EdgeId e : liveEdges(g))
                if (g.source(e) != n && g.target(e) != n) least = std::min(least, near(g.pos(n), g.pos(g.source(e)), g.pos(g.target(e))));
        CHECK(least > 0.4);
    }
    CHECK(squares >= 6);   // several squares, so the clearance was tested between them
}

TEST_CASE("bend settings without an edge kind that bends are a warning", "[angle-layout][bend]") {
    const auto compiled = test::compile("canvas (0, 0) to (5, 5);\nlayout angles { bend_smooth = 3; }\nnode Dot;\n"
                                        "edge Up directed { layout { angle = radians(90); length = 1; } }\naxiom { }\n");
    REQUIRE(compiled.program);
    CHECK(test::diagnosticLines(compiled) ==
          std::vector<std::string>{"2:17: warning: no edge kind bends (`bend = A;` in its layout), so the bend settings do nothing"});
    const auto bent = test::compile("canvas (0, 0) to (5, 5);\nlayout angles { bend_smooth = 3; }\nnode Dot;\n"
                                    "edge Up directed { layout { angle = radians(90); length = 1; bend = 0.1; } }\naxiom { }\n");
    CHECK(test::diagnosticLines(bent).empty());
}
