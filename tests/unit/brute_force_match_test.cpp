// The matching engine against a brute-force matcher: random host graphs and
// random patterns (kinds, wildcards, directed and undirected edges, parallel
// edges, element and cross-element conditions, negative conditions). The
// brute force tries every injective assignment of pattern nodes, then of
// pattern edges, and knows nothing of search plans, anchors or indexes.
// A derivation on each graph then runs with match verification on (test::verified())
// (ctest sets it), so the incrementally kept sets are checked too.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>
#include <sstream>

#include "interp/interpreted_rules.hpp"
#include "interp/run_program.hpp"
#include "brute_force_matcher.hpp"
#include "test_helpers.hpp"

using namespace g2d;
namespace brute = g2d::test::brute;

namespace {

using brute::edgeFits;
using brute::edgeText;
using brute::kindName;
using HostEdge = brute::Edge;   // kind 0: E (directed), 1: U (undirected)
using PatEdge = brute::Edge;
struct Cond {             // nodes[a].v > c, or nodes[a].v < nodes[b].v
    int a, b, c;
};
struct Case {
    std::vector<int> hostKind, hostValue;   // kind 0: A, 1: B
    std::vector<HostEdge> hostEdges;
    std::vector<int> patKind;               // -1: wildcard
    std::vector<PatEdge> patEdges;
    std::vector<Cond> conds;
    // A negative condition: either an edge between two match nodes, or a new
    // node of a kind with an edge from a match node.
    bool nac = false, nacNewNode = false;
    int nacKind = 0, nacFrom = 0, nacTo = 0, nacEdgeKind = 0;
};

std::string source(const Case& c) {
    std::ostringstream s;
    s << "node A { v: int = 0; } node B { v: int = 0; } edge E directed; edge U;\naxiom {\n";
    for (std::size_t i = 0; i < c.hostKind.size(); ++i)
        s << "  h" << i << ": " << kindName(c.hostKind[i]) << " at (" << i << ", 0) { v = " << c.hostValue[i] << " };\n";
    for (const auto& e : c.hostEdges) s << "  " << edgeText("h" + std::to_string(e.src), e.kind, "h" + std::to_string(e.dst)) << ";\n";
    s << "}\nlimit 0;\nrule R {\n  match {\n";
    for (std::size_t i = 0; i < c.patKind.size(); ++i) s << "    p" << i << ": " << kindName(c.patKind[i]) << ";\n";
    for (std::size_t i = 0; i < c.patEdges.size(); ++i)
        s << "    " << edgeText("p" + std::to_string(c.patEdges[i].src), c.patEdges[i].kind, "p" + std::to_string(c.patEdges[i].dst)) << ";\n";
    // A wildcard has no attributes: conditions read its id (the axiom index) instead.
    auto read = [&](int p) { return "p" + std::to_string(p) + (c.patKind[static_cast<std::size_t>(p)] < 0 ? ".id" : ".v"); };
    for (const auto& k : c.conds) {
        if (k.b < 0) s << "    where " << read(k.a) << " > " << k.c << ";\n";
        else s << "    where " << read(k.a) << " < " << read(k.b) << ";\n";
    }
    if (c.nac) {
        if (c.nacNewNode)
            s << "    not { z: " << kindName(c.nacKind) << "; " << edgeText("p" + std::to_string(c.nacFrom), c.nacEdgeKind, "z") << "; }\n";
        else
            s << "    not { " << edgeText("p" + std::to_string(c.nacFrom), c.nacEdgeKind, "p" + std::to_string(c.nacTo)) << "; }\n";
    }
    s << "  }\n  produce {";
    for (std::size_t i = 0; i < c.patKind.size(); ++i) s << " p" << i << ";";
    s << " }\n}\n";
    return s.str();
}

// Every match as (host nodes..., host edges...), by brute force, with the
// case's conditions and negative condition.
brute::Matches bruteForce(const Case& c) {
    const int hn = static_cast<int>(c.hostKind.size());
    brute::Options options;
    options.nodesHold = [&](const std::vector<int>& nodes) {
        auto value = [&](int p) {
            const int h = nodes[static_cast<std::size_t>(p)];
            return c.patKind[static_cast<std::size_t>(p)] < 0 ? h : c.hostValue[static_cast<std::size_t>(h)];
        };
        for (const auto& k : c.conds)
            if (k.b < 0 ? !(value(k.a) > k.c) : !(value(k.a) < value(k.b))) return false;
        return true;
    };
    options.matchHolds = [&](const std::vector<int>& nodes, const std::vector<int>& edges) {   // the negative condition cannot be matched
        if (!c.nac) return true;
        auto used = [&](int e) { return std::find(edges.begin(), edges.end(), e) != edges.end(); };
        const int from = nodes[static_cast<std::size_t>(c.nacFrom)];
        auto edgeTo = [&](int to) {
            for (int e = 0; e < static_cast<int>(c.hostEdges.size()); ++e)
                if (!used(e) && edgeFits(c.hostEdges[static_cast<std::size_t>(e)], c.nacEdgeKind, from, to)) return true;
            return false;
        };
        if (!c.nacNewNode) return !edgeTo(nodes[static_cast<std::size_t>(c.nacTo)]);
        for (int z = 0; z < hn; ++z) {
            if (std::find(nodes.begin(), nodes.end(), z) != nodes.end()) continue;
            if (c.hostKind[static_cast<std::size_t>(z)] == c.nacKind && edgeTo(z)) return false;
        }
        return true;
    };
    return brute::matches({c.hostKind, c.hostEdges}, {c.patKind, c.patEdges}, options);
}

Case randomCase(std::mt19937& gen) {
    auto pick = [&](int n) { return static_cast<int>(gen() % static_cast<unsigned>(n)); };
    Case c;
    const int hn = 4 + pick(7);
    for (int i = 0; i < hn; ++i) {
        c.hostKind.push_back(pick(2));
        c.hostValue.push_back(pick(5));
    }
    const int he = pick(3 * hn);
    for (int i = 0; i < he; ++i) c.hostEdges.push_back({pick(2), pick(hn), pick(hn)});   // self-loops and parallels too
    const int pn = 1 + pick(3);
    for (int i = 0; i < pn; ++i) {
        const int k = pick(5);   // A, B, or (one in five) a wildcard
        c.patKind.push_back(k < 2 ? k : k == 2 ? -1 : pick(2));
    }
    // Connect the pattern (a path or tree), then maybe add an extra edge.
    for (int i = 1; i < pn; ++i) {
        const int other = pick(i);
        c.patEdges.push_back(pick(2) ? PatEdge{pick(2), other, i} : PatEdge{pick(2), i, other});
    }
    if (pn > 1 && pick(3) == 0) c.patEdges.push_back({pick(2), pick(pn), pick(pn)});
    // A wildcard must be on an edge; a lone node has a kind.
    if (pn == 1) c.patKind[0] = c.patKind[0] < 0 ? 0 : c.patKind[0];
    if (pick(2)) c.conds.push_back({pick(pn), -1, pick(4)});
    if (pn > 1 && pick(2)) c.conds.push_back({0, 1, 0});
    if (pick(2)) {
        c.nac = true;
        c.nacNewNode = pn == 1 || pick(2);
        c.nacKind = pick(2);
        c.nacFrom = pick(pn);
        c.nacTo = pn > 1 ? (c.nacFrom + 1 + pick(pn - 1)) % pn : 0;
        c.nacEdgeKind = pick(2);
    }
    return c;
}

}  // namespace

TEST_CASE("the engine finds exactly the matches a brute-force matcher finds", "[match][brute]") {
    std::mt19937 gen(20261123);
    int compared = 0, nonEmpty = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const Case c = randomCase(gen);
        const std::string text = source(c);
        INFO(text);
        auto compiled = test::compile(text);
        REQUIRE(compiled.program);
        const auto& prog = *compiled.program;
        rt::Rng rng(1);
        auto [st, g] = test::startInterpreter(prog, rng);
        interp::InterpretedRules rules(st);
        rt::MatchBuffer found;
        found.reset(static_cast<int>(c.patKind.size()), static_cast<int>(c.patEdges.size()));
        rules.findMatches(0, g, found);
        std::set<std::vector<std::uint32_t>> engine;
        const std::size_t width = c.patKind.size() + c.patEdges.size();
        for (std::size_t i = 0; i < found.size(); ++i) engine.emplace(found.ids(i), found.ids(i) + width);
        CHECK(engine.size() == found.size());   // no match twice
        const auto expected = bruteForce(c);
        CHECK(engine == expected);
        // Every anchored search finds exactly the matches binding its anchor.
        for (std::size_t p = 0; p < c.patKind.size(); ++p)
            for (std::uint32_t h = 0; h < c.hostKind.size(); ++h) {
                if (c.patKind[p] >= 0 && c.hostKind[h] != c.patKind[p]) continue;
                found.reset(static_cast<int>(c.patKind.size()), static_cast<int>(c.patEdges.size()));
                rules.findAnchored(0, g, static_cast<int>(p), h, found);
                std::set<std::vector<std::uint32_t>> anchored, wanted;
                for (std::size_t i = 0; i < found.size(); ++i) anchored.emplace(found.ids(i), found.ids(i) + width);
                for (const auto& m : expected)
                    if (m[p] == h) wanted.insert(m);
                CHECK(anchored == wanted);
            }
        ++compared;
        nonEmpty += !expected.empty();
    }
    CHECK(compared == 400);
    CHECK(nonEmpty > 100);   // the generator makes patterns that do match
}

TEST_CASE("incrementally kept matches equal a full search after every random rewrite", "[match][incremental]") {
    // Rules that add and delete edges and nodes at random on random graphs;
    // the derivation checks every rule's set against a full search after
    // every step (test::verified()).
    std::mt19937 gen(7);
    for (int trial = 0; trial < 60; ++trial) {
        Case c = randomCase(gen);
        std::string text = source(c);
        text.replace(text.find("limit 0;"), 8, "limit 40;");
        // Daughters that rewire: drop the first pattern edge, add an edge and a node.
        const auto produce = text.find("  produce {");
        std::string daughter = "  produce {";
        for (std::size_t i = 0; i < c.patKind.size(); ++i) daughter += " p" + std::to_string(i) + ";";
        daughter += " n: A at (0, 1) { v = " + std::to_string(trial % 5) + " }; p0 -[E]-> n;";
        if (c.patKind.size() > 1) daughter += " p1 -[U]- n;";
        daughter += " }\n}\nrule Prune { match { x: A; y: B; x -[E]-> y; } produce { x; } }\n";
        text = text.substr(0, produce) + daughter;
        INFO(text);
        auto compiled = test::compile(text);
        REQUIRE(compiled.program);
        auto run = interp::runProgram(*compiled.program, interp::defaultParams(*compiled.program), 1 + trial, test::verified());
        CHECK(run.derivation.steps <= 40);
    }
}

namespace {

// A random grammar of three node kinds and three edge kinds whose rules each
// read and change a few kinds and attributes (new and deleted nodes and
// edges, attributes read and unread, moves and positions read, rewired
// edges, wildcards, negative conditions, degrees), so that many steps leave
// some rules' sets, or their matches at some nodes, alone
// (RuleInfo::readKinds, readValues).
std::string kindedGrammar(std::mt19937& gen) {
    auto pick = [&](int n) { return static_cast<int>(gen() % static_cast<unsigned>(n)); };
    const char* nodeKinds[] = {"A", "B", "C"};
    const char* edgeKinds[] = {"E", "F", "U"};
    auto node = [&] { return std::string(nodeKinds[pick(3)]); };
    auto arrow = [&](int k) { return k == 2 ? std::string(" -[U]- ") : std::string(" -[") + edgeKinds[k] + "]-> "; };
    std::ostringstream s;
    s << "node A { v: int = 0; u: int = 0; } node B { v: int = 0; u: int = 0; } node C { v: int = 0; u: int = 0; }\n"
         "edge E directed; edge F directed; edge U;\naxiom {\n";
    const int hosts = 5 + pick(6);
    for (int i = 0; i < hosts; ++i) s << "  h" << i << ": " << node() << " at (" << i << ", " << pick(3) << ");\n";
    for (int i = 0, n = 4 + pick(8); i < n; ++i) s << "  h" << pick(hosts) << arrow(pick(3)) << "h" << pick(hosts) << ";\n";
    s << "}\nlimit 60;\n";
    for (int r = 0, n = 3 + pick(4); r < n; ++r) {
        // A wildcard only where a pattern edge binds it.
        const std::string w = pick(5) == 0 ? "*" : node(), x = node(), y = node(), z = node();
        const int k = pick(3), k2 = pick(3);
        s << "rule R" << r << " priority " << pick(3) << " {\n  match { ";
        switch (pick(10)) {
        case 0:   // an edge where there is none
            s << "x: " << x << "; y: " << y << "; not { x" << arrow(k) << "y; } } produce { x; y; x" << arrow(k) << "y; }";
            break;
        case 1:   // an edge goes
            s << "x: " << w << "; y: " << y << "; e: x" << arrow(k) << "y; } produce { x; y; }";
            break;
        case 2:   // a new node, and a value
            s << "x: " << y << " where x.v < 3; } produce { x { v = x.v + 1 }; n: " << z << " at (1, 1); x" << arrow(k) << "n; }";
            break;
        case 3:   // a node with enough edges goes
            s << "x: " << x << " where x.degree >= " << 1 + pick(3) << "; } produce { }";
            break;
        case 4:   // a rewired edge
            s << "x: " << w << "; y: " << y << "; e: x" << arrow(k) << "y; } produce { x; y; e: y" << arrow(k) << "x; }";
            break;
        case 5:   // a move, unless a neighbour of some kind is there
            s << "x: " << y << " where x.pos.x < 6; not { w: " << z << " where w.v > 1; x" << arrow(k2) << "w; } } produce { x at x.pos + (1, 0); }";
            break;
        case 6:   // reads a position
            s << "x: " << y << " where x.pos.x > 3 and x.v < 4; } produce { x { v = x.v + 2 }; }";
            break;
        case 7:   // writes an attribute no condition reads, at a node others bind
            s << "x: " << x << " where x.v < 4; y: " << y << "; e: x" << arrow(k) << "y; } produce { x { u = x.u + 1 }; y; e; }";
            break;
        case 8:   // writes an attribute others read, and reads the other one
            s << "x: " << y << " where x.u < 5; } produce { x { v = x.v + 1, u = x.u + 1 }; }";
            break;
        default:   // reads two kinds, changes a third
            s << "x: " << w << "; y: " << y << "; e: x" << arrow(k) << "y; } produce { x; y; e; n: " << z << " at (0, 2); y" << arrow(k2) << "n; }";
            break;
        }
        s << "\n}\n";
    }
    return s.str();
}

}  // namespace

TEST_CASE("sets left alone by steps that change no kind their rules read equal a full search", "[match][incremental]") {
    // Every step's changed kinds are checked against what each rule reads;
    // the derivation checks every rule's set against a full search after
    // every step (test::verified()), so a set wrongly
    // left alone fails the run.
    std::mt19937 gen(11);
    long long skipped = 0, repaired = 0;
    int ran = 0;
    for (int trial = 0; trial < 150; ++trial) {
        const std::string text = kindedGrammar(gen);
        INFO(text);
        auto compiled = test::compile(text);
        REQUIRE(compiled.program);
        auto run = interp::runProgram(*compiled.program, interp::defaultParams(*compiled.program), 1 + trial, test::verified());
        skipped += run.derivation.setRepairsSkipped;
        repaired += run.derivation.setRepairs;
        ran += run.derivation.steps > 0;
    }
    CHECK(ran > 100);
    // The grammars do exercise it: many sets are left alone, many repaired.
    CHECK(skipped > 1000);
    CHECK(repaired > 1000);
}
