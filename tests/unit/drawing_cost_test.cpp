// `layout angles { cost = …; temperature = …; }` (drawing_cost.hpp): the
// derivation is a Metropolis chain. A tiny grammar whose states are the
// counts (a, b) of two node kinds is run from many seeds, and the share of
// runs in each state after k steps is compared with the distribution a
// brute-force reference computes from the documented semantics alone: rules
// chosen by weight among those that match, a proposal that raises the cost
// by d accepted with probability exp(-d / T), a refused one changing nothing.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "g2d/connected_guard.hpp"
#include "g2d/drawing_cost.hpp"
#include "interp/run_program.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

constexpr int kCap = 12;   // states beyond this many nodes of a kind are never reached in kSteps
constexpr int kSteps = 10;
constexpr int kRuns = 3000;

const char* const kGrammar = R"(
param temperature_param: float = 1.3;
canvas (0, 0) to (1000, 1000);
layout angles {
    cost = 0.6 * abs(count(A) - 2) + 0.9 * count(B) + 0.1 * nodes;
    temperature = temperature_param;
}
node A { style { tag = "none"; } }
node B { style { tag = "none"; } }
edge Unused directed { layout { angle = 0; length = 1; } }
axiom { }
limit 10;
rule AddA dpo weight 2 { match { } produce { a: A; } }
rule AddB dpo weight 1 { match { } produce { b: B; } }
rule RemoveA dpo weight 1.5 { match { a: A; } produce { } }
rule RemoveB dpo weight 1 { match { b: B; } produce { } }
)";

double costOf(int a, int b) { return 0.6 * std::abs(a - 2) + 0.9 * b + 0.1 * (a + b); }

// The exact distribution of (a, b) after `steps` steps from (0, 0).
std::map<std::pair<int, int>, double> reference(int steps, double temperature) {
    std::map<std::pair<int, int>, double> p{{{0, 0}, 1.0}};
    for (int s = 0; s < steps; ++s) {
        std::map<std::pair<int, int>, double> next;
        for (const auto& [state, mass] : p) {
            const auto [a, b] = state;
            // (weight, the state it proposes), for the rules that match
            std::vector<std::pair<double, std::pair<int, int>>> moves{{2.0, {a + 1, b}}, {1.0, {a, b + 1}}};
            if (a > 0) moves.push_back({1.5, {a - 1, b}});
            if (b > 0) moves.push_back({1.0, {a, b - 1}});
            double total = 0;
            for (const auto& m : moves) total += m.first;
            for (const auto& [w, to] : moves) {
                const double d = costOf(to.first, to.second) - costOf(a, b);
                const double accept = d <= 0 ? 1.0 : std::exp(-d / temperature);
                next[to] += mass * w / total * accept;
                next[state] += mass * w / total * (1 - accept);
            }
        }
        p = std::move(next);
    }
    return p;
}

std::map<std::pair<int, int>, double> sampled(const ir::Program& prog, double temperature) {
    std::vector<rt::Value> params = interp::defaultParams(prog);
    params[0] = temperature;
    std::map<std::pair<int, int>, double> share;
    for (int seed = 1; seed <= kRuns; ++seed) {
        const interp::RunResult r = interp::runProgram(prog, params, static_cast<std::uint64_t>(seed), rt::RunSettings{});
        int a = 0, b = 0;
        for (rt::NodeId n : r.graph().allNodes()) (prog.kinds[static_cast<std::size_t>(r.graph().nodeKind(n))].name == "A" ? a : b)++;
        REQUIRE(a <= kCap);
        REQUIRE(b <= kCap);
        REQUIRE(r.derivation.steps == kSteps);
        share[{a, b}] += 1.0 / kRuns;
    }
    return share;
}

}  // namespace

TEST_CASE("a cost makes the derivation a Metropolis chain: the states after k steps match a brute-force reference",
          "[drawing_cost]") {
    const CompileResult compiled = test::compile(kGrammar);
    INFO(test::firstError(compiled));
    REQUIRE(compiled.program);
    for (const double temperature : {1.3, 0.4}) {
        INFO("temperature " << temperature);
        const auto want = reference(kSteps, temperature);
        const auto got = sampled(*compiled.program, temperature);
        double covered = 0;
        for (const auto& [state, p] : want) {
            INFO("state (" << state.first << ", " << state.second << "): reference " << p);
            const double q = got.count(state) ? got.at(state) : 0.0;
            // Four standard errors of a share of kRuns runs, and a little for rare states.
            CHECK(std::abs(q - p) <= 4 * std::sqrt(p * (1 - p) / kRuns) + 0.002);
            covered += q;
        }
        CHECK(covered == Approx(1.0));   // no run ended in a state the reference calls impossible
    }
}

TEST_CASE("counts follow applications: count(K), nodes and edges", "[drawing_cost]") {
    rt::Graph g({rt::KindInfo{rt::ElemClass::Node, false}, rt::KindInfo{rt::ElemClass::Edge, true}});
    // The counts of a graph are its live elements by kind.
    const int a = 0, e = 1;
    const rt::NodeId n0 = g.addNode(a, {0, 0}, 0), n1 = g.addNode(a, {1, 0}, 0);
    g.addEdge(e, n0, n1, 0);
    rt::KindCounts c = rt::KindCounts::of(g, 2);
    CHECK(c[a] == 2);
    CHECK(c[e] == 1);
    CHECK(c[rt::KindCounts::kNodes] == 2);
    CHECK(c[rt::KindCounts::kEdges] == 1);
    // Deleting node 0 takes its edge with it; a new node and edge are added.
    rt::DaughterShape shape;
    shape.deletedNodes = {0};
    shape.newNodes = 1;
    shape.newNodeKinds = {a};
    shape.newEdges = {{1, -1, e}};
    const rt::NodeId nodes[] = {n0, n1};
    const rt::EdgeId edges[] = {rt::kNoId};
    rt::Match m;
    m.nodes = nodes;
    m.edges = edges;
    rt::countChange(g, shape, m, c);
    CHECK(c[a] == 2);
    CHECK(c[e] == 1);
    CHECK(c[rt::KindCounts::kNodes] == 2);
    CHECK(c[rt::KindCounts::kEdges] == 1);
}

TEST_CASE("the Metropolis test accepts a cost rise d with probability exp(-d / T), and never draws for a fall",
          "[drawing_cost]") {
    rt::Rng rng(7), untouched(7);
    CHECK(rt::metropolisAccepts(-1, 1, rng));
    CHECK(rt::metropolisAccepts(0, 1, rng));
    CHECK(rng.unit() == untouched.unit());   // nothing drawn
    int accepted = 0;
    constexpr int kTries = 20000;
    for (int i = 0; i < kTries; ++i) accepted += rt::metropolisAccepts(1.5, 2.0, rng) ? 1 : 0;
    CHECK(static_cast<double>(accepted) / kTries == Approx(std::exp(-0.75)).margin(0.015));
}

TEST_CASE("connected = true refuses an application that splits what it touches or deletes the last node", "[drawing_cost]") {
    // A path a - b - c - d, and an edge d - a closing it into a cycle on demand.
    rt::Graph g({rt::KindInfo{rt::ElemClass::Node, false}, rt::KindInfo{rt::ElemClass::Edge, true}});
    std::vector<rt::NodeId> n;
    for (int i = 0; i < 4; ++i) n.push_back(g.addNode(0, {static_cast<double>(i), 0}, 0));
    std::vector<rt::EdgeId> e;
    for (int i = 0; i < 3; ++i) e.push_back(g.addEdge(1, n[i], n[i + 1], 0));
    rt::ConnectedGuard guard;
    auto deletesEdge = [&](rt::EdgeId which) {
        rt::DaughterShape shape;
        shape.deletedEdges = {0};
        const rt::NodeId nodes[] = {g.source(which), g.target(which)};
        const rt::EdgeId edges[] = {which};
        return guard.keepsConnected(g, shape, rt::Match{nodes, edges, nullptr});
    };
    CHECK_FALSE(deletesEdge(e[1]));   // b - c cut: {a, b} and {c, d}
    CHECK_FALSE(deletesEdge(e[0]));   // a alone
    const rt::EdgeId closing = g.addEdge(1, n[3], n[0], 0);
    CHECK(deletesEdge(e[1]));         // the cycle still joins b and c
    CHECK(deletesEdge(closing));
    {
        // A new node joined to b and d by new edges keeps them together when b - c and c - d go with c.
        rt::DaughterShape shape;
        shape.deletedNodes = {2};
        shape.newNodes = 1;
        shape.newNodeKinds = {0};
        shape.newEdges = {{0, -1, 1}, {-1, 1, 1}};
        const rt::NodeId nodes[] = {n[1], n[3], n[2]};
        CHECK(guard.keepsConnected(g, shape, rt::Match{nodes, nullptr, nullptr}));
    }
    {
        // Deleting every node empties the graph: refused.
        rt::DaughterShape shape;
        shape.deletedNodes = {0, 1, 2, 3};
        const rt::NodeId nodes[] = {n[0], n[1], n[2], n[3]};
        CHECK_FALSE(guard.keepsConnected(g, shape, rt::Match{nodes, nullptr, nullptr}));
    }
}
