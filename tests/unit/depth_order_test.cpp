// A 3D grammar's SVG paints faces, edges and nodes in one depth order
// (projection.hpp, draw_order.cpp): an edge behind a face comes before it and
// is hidden, one in front after it, and a face's own sides after it even
// where they lie farther than its centre; 2D keeps faces below edges below
// nodes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "g2d/projection.hpp"
#include "g2d/svg_writer.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

// The SVG of a snippet's axiom, as `g2d run` draws it (3D: from the default view).
std::string axiomSvg(const std::string& source) {
    rt::RunSettings settings;
    settings.steps = 0;
    auto r = test::runSnippet(source, 1, settings);
    REQUIRE(r.grammar);
    const rt::Graph& g = r.grammar->graph();
    const rt::ViewProjection view = rt::viewFrom(rt::kDefaultViewFrom);
    const bool space3d = r.grammar->jsonSchema().space3d;
    rt::StringOut out;
    const rt::SolidFaces solid(g);
    rt::writeSvg(g, [&](rt::ElemClass cls, std::uint32_t id, rt::DrawItem& it) {
        r.grammar->drawItem(cls, id, it);
        if (space3d) rt::projectItem(it, g, view, solid);
    }, r.grammar->svgDefs(), out);
    return out.text();
}

// The colours of the drawn elements, in the SVG's order.
std::vector<std::string> paintOrder(const std::string& svg) {
    std::vector<std::string> order;
    for (std::size_t at = svg.find('#'); at != std::string::npos; at = svg.find('#', at + 1)) order.push_back(svg.substr(at, 7));
    return order;
}

// A square wall in the plane y = 0 facing the viewer (who looks from
// (1, -2, 1.5)), its four sides (green), an edge behind it at y = 1 (blue)
// and one in front at y = -1 (red), both across its middle.
const char* const kScene = R"(%s
node P { style { tag = "none"; } }
edge Side { style { stroke = "#00ff00"; } }
edge Behind { style { stroke = "#0000ff"; } }
edge Before { style { stroke = "#ff0000"; } }
face Wall { style { fill = "#888888"; } }
axiom {
    a: P at %s; b: P at %s; c: P at %s; d: P at %s;
    a -[Side]- b; b -[Side]- c; c -[Side]- d; d -[Side]- a;
    Wall(a, b, c, d);
    p: P at %s; q: P at %s; p -[Behind]- q;
    s: P at %s; t: P at %s; s -[Before]- t;
}
)";

std::string scene(bool in3d) {
    auto at = [&](double x, double y, double z) {
        return in3d ? "(" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + ")"
                    : "(" + std::to_string(x) + ", " + std::to_string(z) + ")";
    };
    char text[2048];
    std::snprintf(text, sizeof text, kScene, in3d ? "space 3d;" : "", at(0, 0, 0).c_str(), at(1, 0, 0).c_str(), at(1, 0, 1).c_str(),
                  at(0, 0, 1).c_str(), at(-0.5, 1, 0.5).c_str(), at(1.5, 1, 0.5).c_str(), at(-0.5, -1, 0.3).c_str(),
                  at(1.5, -1, 0.3).c_str());
    return text;
}

}  // namespace

TEST_CASE("3D: faces, edges and nodes are painted in one depth order", "[output][svg][3d]") {
    const std::vector<std::string> order = paintOrder(axiomSvg(scene(true)));
    // The edge behind the wall, the wall, its sides (all four: the bottom one
    // lies farther than the wall's centre), then the edge in front.
    CHECK(order == std::vector<std::string>{"#0000ff", "#888888", "#00ff00", "#00ff00", "#00ff00", "#00ff00", "#ff0000"});
}

TEST_CASE("3D: the edges of a closed surface's back go below its front", "[output][svg][3d]") {
    // A tetrahedron oriented outwards: its back face's three sides that no
    // front face has are drawn before every front face.
    const std::string svg = axiomSvg(R"(space 3d;
node P { style { tag = "none"; } }
edge E { style { stroke = "#00ff00"; } }
face Bottom { style { fill = "#111111"; } }
face Left { style { fill = "#222222"; } }
face Front { style { fill = "#eeeeee"; } }
axiom {
    a: P at (0, 0, 0); b: P at (1, 0, 0); c: P at (0, 1, 0); d: P at (0, 0, 1);
    a -[E]- b; b -[E]- c; c -[E]- a; a -[E]- d; b -[E]- d; c -[E]- d;
    Bottom(a, c, b); Front(a, b, d); Front(b, c, d); Left(c, a, d);
}
)");
    const std::vector<std::string> order = paintOrder(svg);
    REQUIRE(order.size() == 10);
    // Seen from (1, -2, 1.5) the faces a-c-b (bottom) and c-a-d (x = 0) show
    // their backs: they and the side a-c they share (hidden) are painted
    // before the two front faces; the other five sides each bound a front
    // face and come after it.
    const auto firstFront = std::find(order.begin(), order.end(), std::string("#eeeeee")) - order.begin();
    const std::vector<std::string> back(order.begin(), order.begin() + firstFront);
    CHECK(back.size() == 3);
    CHECK(std::count(back.begin(), back.end(), std::string("#111111")) == 1);
    CHECK(std::count(back.begin(), back.end(), std::string("#222222")) == 1);
    CHECK(std::count(back.begin(), back.end(), std::string("#00ff00")) == 1);
    CHECK(order.back() == "#00ff00");
}

TEST_CASE("2D: faces below edges below nodes, whatever the places", "[output][svg]") {
    const std::vector<std::string> order = paintOrder(axiomSvg(scene(false)));
    CHECK(order == std::vector<std::string>{"#888888", "#00ff00", "#00ff00", "#00ff00", "#00ff00", "#0000ff", "#ff0000"});
}

TEST_CASE("3D: an open box, its faces oriented inwards, is sorted by depth alone", "[output][svg][3d]") {
    // g3_box's open box: a bottom and four walls, every normal inwards, seen
    // from above. Not a closed surface, so no face counts as a hidden back:
    // the far bottom corner stays below the front walls, the near top corner
    // is painted last.
    const std::string svg = axiomSvg(R"(space 3d;
node P { style { tag = "none"; } }
node Far { style { fill = "#00ffff"; } }
node Near { style { fill = "#ff00ff"; } }
face Box { style { fill = "#aaaaaa"; } }
face FrontWall { style { fill = "#111111"; } }
face RightWall { style { fill = "#222222"; } }
axiom {
    a: P at (0, 0, 0); b: P at (1, 0, 0); c: P at (1, 1, 0); d: Far at (0, 1, 0);
    e: P at (0, 0, 1); f: Near at (1, 0, 1); g: P at (1, 1, 1); h: P at (0, 1, 1);
    Box(a, b, c, d);
    FrontWall(b, a, e, f); RightWall(c, b, f, g); Box(d, c, g, h); Box(a, d, h, e);
}
)");
    const std::vector<std::string> order = paintOrder(svg);
    REQUIRE(order.size() == 7);
    CHECK(order.back() == "#ff00ff");
    const auto at = [&](const char* colour) { return std::find(order.begin(), order.end(), std::string(colour)) - order.begin(); };
    CHECK(at("#00ffff") < at("#111111"));
    CHECK(at("#00ffff") < at("#222222"));
}

TEST_CASE("3D: a node stays on top of its edges, even at their far end", "[output][svg][3d]") {
    // A wire going from far (behind, y = 1) to near (y = -1): its far end's
    // node lies farther than the wire's midpoint, and is still painted after it.
    const std::vector<std::string> order = paintOrder(axiomSvg(R"(space 3d;
node Far { style { fill = "#00ffff"; } }
node Near { style { fill = "#ff00ff"; } }
edge Wire { style { stroke = "#00ff00"; } }
axiom { p: Far at (0, 1, 0); q: Near at (0, -1, 0); p -[Wire]- q; }
)"));
    CHECK(order == std::vector<std::string>{"#00ff00", "#00ffff", "#ff00ff"});
}
