// The AGTIVE 2007 Sierpinski case: counts by formula and exact geometry.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iterator>
#include <set>

#include "interp/run_program.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

using Point = std::pair<long long, long long>;
Point key(rt::vec2 p) { return {std::llround(p.x * 1e9), std::llround(p.y * 1e9)}; }

// Corners of the generation-g triangles, computed independently.
void corners(rt::vec2 a, rt::vec2 b, rt::vec2 c, int g, std::set<Point>& out,
             std::multiset<std::pair<Point, Point>>& edges) {
    if (g == 0) {
        for (auto p : {a, b, c}) out.insert(key(p));
        edges.insert({key(a), key(b)});
        edges.insert({key(b), key(c)});
        edges.insert({key(c), key(a)});
        return;
    }
    const rt::vec2 ab = (a + b) / 2.0, bc = (b + c) / 2.0, ca = (c + a) / 2.0;
    corners(a, ab, ca, g - 1, out, edges);
    corners(ab, b, bc, g - 1, out, edges);
    corners(ca, bc, c, g - 1, out, edges);
}

}  // namespace

TEST_CASE("Sierpinski: node and edge counts follow the formula, geometry is exact (g <= 8)", "[examples][sierpinski]") {
    std::ifstream in(std::string(G2D_SOURCE_DIR) + "/examples/sierpinski.g2d");
    auto compiled = test::compile(std::string(std::istreambuf_iterator<char>(in), {}));
    REQUIRE(compiled.program);
    for (long long g = 0; g <= 8; ++g) {
        INFO("generation " << g);
        auto run = interp::runProgram(*compiled.program, {g}, 1, test::verified());
        const rt::Graph& graph = run.graph();
        const auto p3 = static_cast<std::size_t>(std::pow(3, g + 1));
        CHECK(run.derivation.steps == g);
        CHECK(run.derivation.stopped == rt::StopReason::Terminal);
        CHECK(graph.nodeCount() == (p3 + 3) / 2);
        CHECK(graph.edgeCount() == p3);
        std::set<Point> expectedNodes, actualNodes;
        std::multiset<std::pair<Point, Point>> expectedEdges, actualEdges;
        corners({0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}, static_cast<int>(g), expectedNodes, expectedEdges);
        for (rt::NodeId n : graph.allNodes()) actualNodes.insert(key(graph.pos(n)));
        const double side = std::ldexp(1.0, static_cast<int>(-g));
        bool sidesExact = true;
        for (rt::EdgeId e = 0; e < graph.edgeCapacity(); ++e) {
            if (!graph.edgeAlive(e)) continue;
            const rt::vec2 a = graph.pos(graph.source(e)), b = graph.pos(graph.target(e));
            actualEdges.insert({key(a), key(b)});
            sidesExact = sidesExact && std::abs(rt::length(b - a) - side) < 1e-12;
        }
        CHECK(actualNodes.size() == graph.nodeCount());  // no two nodes at one place
        CHECK(actualNodes == expectedNodes);
        CHECK(actualEdges == expectedEdges);
        CHECK(sidesExact);
    }
}
