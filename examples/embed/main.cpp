// Embeds two compiled grammars through g2d's C++ API: sets parameters and a
// seed, derives, reads the graph and exports it.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <g2d/grammar.hpp>

G2D_DECLARE_GRAMMAR(koch)
G2D_DECLARE_GRAMMAR(sierpinski)

int main(int argc, char** argv) {
    using g2d::rt::ElemClass;
    g2d::Grammar koch(g2d_grammar_koch(), "koch_snowflake.g2d");
    koch.set("max_lod", "3");
    koch.setSeed(7);
    const auto result = koch.derive();
    const g2d::GraphView graph = koch.view();
    std::printf("koch: %lld steps, %zu nodes, %zu edges\n", result.steps, graph.count(ElemClass::Node),
                graph.count(ElemClass::Edge));
    long long deepest = 0;
    for (std::uint32_t e = 0; e < graph.capacity(ElemClass::Edge); ++e)
        if (graph.alive(ElemClass::Edge, e)) deepest = std::max(deepest, std::get<long long>(koch.attribute(ElemClass::Edge, e, "lod")));
    std::printf("koch: deepest lod %lld\n", deepest);

    g2d::Grammar sierpinski(g2d_grammar_sierpinski(), "sierpinski.g2d");
    sierpinski.set("generations", "4");
    sierpinski.derive();
    const g2d::GraphView triangle = sierpinski.view();
    std::printf("sierpinski: %zu nodes, %zu edges\n", triangle.count(ElemClass::Node), triangle.count(ElemClass::Edge));

    if (argc > 1) {
        std::ofstream(argv[1]) << koch.svg();
        if (argc > 2) std::ofstream(argv[2]) << koch.json();
    }
    const bool ok = graph.count(ElemClass::Edge) == 192 && deepest == 3 && triangle.count(ElemClass::Edge) == 243;
    if (!ok) std::fprintf(stderr, "unexpected result\n");
    return ok ? 0 : 1;
}
