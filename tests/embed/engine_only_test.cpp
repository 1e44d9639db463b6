// A program that embeds two compiled grammars through <g2d/grammar.hpp>
// alone and links only g2d_engine (tests/embed/CMakeLists.txt): it checks
// what it reads through the API (GraphView, attributes) and writes the
// SVG, JSON and OBJ it derived into the folder given, for
// engine_only_test.sh to compare with `g2d run`.
// Usage: g2d_embed_engine_only OUT_DIR
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <g2d/grammar.hpp>

G2D_DECLARE_GRAMMAR(koch_snowflake)
G2D_DECLARE_GRAMMAR(g3_box)

namespace {

using g2d::rt::ElemClass;

int failures = 0;

void check(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "FAIL: %s\n", what);
        ++failures;
    }
}

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// Koch's snowflake at level 2: a triangle whose sides were each cut into 4, twice.
void koch(const std::string& dir) {
    g2d::Grammar g(g2d_grammar_koch_snowflake(), "koch_snowflake.g2d");
    g.set("max_lod", "2");
    g.setSeed(7);
    const g2d::rt::DerivationResult result = g.derive();
    check(result.stopped == g2d::rt::StopReason::Terminal, "koch: the derivation ends by itself");
    const g2d::GraphView view = g.view();
    check(view.count(ElemClass::Edge) == 48, "koch: 3 * 4^2 edges");
    check(view.count(ElemClass::Node) == 48, "koch: a closed curve, as many nodes as edges");
    check(view.count(ElemClass::Face) == 0, "koch: no faces");
    long long deepest = 0;
    std::size_t live = 0;
    for (std::uint32_t e = 0; e < view.capacity(ElemClass::Edge); ++e) {
        if (!view.alive(ElemClass::Edge, e)) continue;
        ++live;
        deepest = std::max(deepest, std::get<long long>(g.attribute(ElemClass::Edge, e, "lod")));
        check(view.alive(ElemClass::Node, view.source(e)) && view.alive(ElemClass::Node, view.target(e)), "koch: edges join live nodes");
    }
    check(live == view.count(ElemClass::Edge), "koch: the live ids are as many as the count");
    check(deepest == 2, "koch: the deepest lod is max_lod");
    const std::string svg = g.svg();
    check(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0,
          "koch: the SVG starts with its prolog and root element");
    write(dir + "/koch.svg", svg);
    write(dir + "/koch.json", g.json());
    write(dir + "/koch.obj", g.obj("koch.run.mtl"));
    write(dir + "/koch.mtl", g.mtl());
}

// G^3's box (examples/g3_box.g2d): merged, a closed box of 8 corners in 3D.
void box(const std::string& dir) {
    g2d::Grammar g(g2d_grammar_g3_box(), "g3_box.g2d");
    g.setSeed(3);
    g.derive();
    const g2d::GraphView view = g.view();
    check(view.count(ElemClass::Node) == 8, "box: 8 corners");
    check(view.count(ElemClass::Edge) == 12, "box: 12 edges");
    check(view.count(ElemClass::Face) == 5, "box: 5 faces");
    int top = 0;
    for (std::uint32_t n = 0; n < view.capacity(ElemClass::Node); ++n) {
        if (!view.alive(ElemClass::Node, n)) continue;
        const double z = view.position(n).z;
        check(z == 0 || std::abs(z - 1) < 1e-9, "box: corners at the bottom or at height 1");
        top += z > 0.5;
        check(view.kindName(ElemClass::Node, n) == "N", "box: nodes of kind N");
    }
    check(top == 4, "box: 4 corners on top");
    for (std::uint32_t f = 0; f < view.capacity(ElemClass::Face); ++f) {
        if (!view.alive(ElemClass::Face, f)) continue;
        check(view.kindName(ElemClass::Face, f) == "F", "box: faces of kind F");
        check(view.corners(f).size() == 4, "box: every face a quadrilateral");
    }
    write(dir + "/box.svg", g.svg());
    write(dir + "/box.json", g.json());
    write(dir + "/box.obj", g.obj("box.run.mtl"));
    write(dir + "/box.mtl", g.mtl());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
        return 2;
    }
    koch(argv[1]);
    box(argv[1]);
    return failures == 0 ? 0 : 1;
}
