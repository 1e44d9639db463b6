// The drawing step builds each proposal's system from the part of the graph
// the change can move, with the rest from a spatial index (AngleStep): the
// drawings must be exactly those the whole graph gives (same positions,
// bit for bit), for every inferred grammar without areas and for a grammar
// whose changes free vertices and place new pieces anywhere.
#include <catch2/catch.hpp>

#include <sstream>

#include "g2d/json_writer.hpp"
#include "infer/grammar_writer.hpp"
#include "infer_examples.hpp"
#include "interp/drawing.hpp"
#include "interp/run_program.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

// Every live node's id and exact position, and every live edge.
std::string drawing(const rt::Graph& g) {
    std::ostringstream out;
    out.precision(17);
    for (rt::NodeId n = 0; n < g.nodeCapacity(); ++n)
        if (g.nodeAlive(n)) out << n << ' ' << g.pos(n).x << ' ' << g.pos(n).y << '\n';
    for (rt::EdgeId e = 0; e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) out << 'e' << e << ' ' << g.source(e) << ' ' << g.target(e) << '\n';
    return out.str();
}

void sameEitherWay(const ir::Program& prog, std::uint64_t seed, long long steps) {
    rt::RunSettings part, whole;
    part.steps = whole.steps = steps;
    whole.wholeDrawings = true;
    const interp::RunResult a = interp::runProgram(prog, interp::defaultParams(prog), seed, part);
    const interp::RunResult b = interp::runProgram(prog, interp::defaultParams(prog), seed, whole);
    CHECK(a.derivation.rejectedDrawings == b.derivation.rejectedDrawings);
    CHECK(a.graph().nodeCount() == b.graph().nodeCount());
    CHECK(drawing(a.graph()) == drawing(b.graph()));
}

}  // namespace

TEST_CASE("a proposal drawn from its part equals the whole graph's drawing: inferred grammars without areas", "[angle-layout][infer]") {
    int compared = 0;
    for (const auto& [path, ex] : test::merrellExamples()) {
        bool areas = false;
        for (const auto& l : ex.labels) areas = areas || l.left >= 0 || l.right >= 0;
        if (areas) continue;   // areas are tested over the whole drawing either way
        INFO(path);
        infer::WriterOptions writer;
        const std::string text = infer::writeGrammar(ex, infer::inferGrammar(ex, test::smallHierarchy()), writer);
        const CompileResult compiled = test::compile(text, "inferred.g2d");
        REQUIRE(compiled.program);
        for (std::uint64_t seed : {1, 2}) sameEitherWay(*compiled.program, seed, 600);
        ++compared;
    }
    CHECK(compared >= 10);
}

TEST_CASE("a proposal drawn from its part equals the whole graph's drawing: freed corners, pieces anywhere", "[angle-layout]") {
    // Squares of flexible size placed anywhere; a bridge joins two of them
    // level, freeing corners (up to proposals - 1 of them) to do so.
    const std::string grammar = R"(
canvas (0, 0) to (14, 14);
layout angles { proposals = 6; }
node Corner { style { tag = "none"; } }
edge R directed { layout { angle = 0; min_length = 0.5; max_length = 2; } }
edge U directed { layout { angle = radians(90); min_length = 0.5; max_length = 2; } }
edge L directed { layout { angle = radians(180); min_length = 0.5; max_length = 2; } }
edge D directed { layout { angle = radians(270); min_length = 0.5; max_length = 2; } }
edge Bridge directed { layout { angle = 0; min_length = 0.2; max_length = 3; } }
axiom { }
rule Square dpo weight 1 {
    match { }
    produce { a: Corner; b: Corner; c: Corner; d: Corner; a -[R]-> b; b -[U]-> c; c -[L]-> d; d -[D]-> a; }
}
rule Join dpo weight 4 {
    match { x: Corner; p: Corner; q: Corner; z: Corner; e: x -[R]-> p; f: q -[R]-> z; where distance(p.pos, q.pos) <= 3; not { p -[Bridge]-> q; } }
    produce { x; p; q; z; e; f; p -[Bridge]-> q; }
}
rule Unjoin dpo weight 1 {
    match { p: Corner; q: Corner; b: p -[Bridge]-> q; }
    produce { p; q; }
}
)";
    const CompileResult compiled = test::compile(grammar);
    INFO(test::firstError(compiled));
    REQUIRE(compiled.program);
    for (std::uint64_t seed : {1, 2, 3}) sameEitherWay(*compiled.program, seed, 400);
}
