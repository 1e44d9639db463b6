// Embeds two compiled grammars through g2d's C++ API: sets parameters and a
// seed, derives, reads the graph and exports it.
#include <cstdio>
#include <fstream>
#include <g2d/grammar.hpp>

G2D_DECLARE_GRAMMAR(koch)
G2D_DECLARE_GRAMMAR(sierpinski)

int main(int argc, char** argv) {
    g2d::Grammar koch(g2d_grammar_koch(), "koch_snowflake.g2d");
    koch.set("max_lod", "3");
    koch.setSeed(7);
    const auto result = koch.derive();
    const auto& graph = koch.graph();
    std::printf("koch: %lld steps, %zu nodes, %zu edges\n", result.steps, graph.nodeCount(), graph.edgeCount());
    long long deepest = 0;
    for (g2d::rt::EdgeId e = 0; e < graph.edgeCapacity(); ++e)
        if (graph.edgeAlive(e)) deepest = std::max(deepest, std::get<long long>(koch.attribute(g2d::rt::ElemClass::Edge, e, "lod")));
    std::printf("koch: deepest lod %lld\n", deepest);

    g2d::Grammar sierpinski(g2d_grammar_sierpinski(), "sierpinski.g2d");
    sierpinski.set("generations", "4");
    sierpinski.derive();
    std::printf("sierpinski: %zu nodes, %zu edges\n", sierpinski.graph().nodeCount(), sierpinski.graph().edgeCount());

    if (argc > 1) {
        std::ofstream(argv[1]) << koch.svg();
        if (argc > 2) std::ofstream(argv[2]) << koch.json();
    }
    const bool ok = graph.edgeCount() == 192 && deepest == 3 && sierpinski.graph().edgeCount() == 243;
    if (!ok) std::fprintf(stderr, "unexpected result\n");
    return ok ? 0 : 1;
}
