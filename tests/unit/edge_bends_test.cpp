// Bent edges (Merrell's Appendix B, edge_bends.hpp): after a `layout
// angles` run, edges of kinds with `bend` are polylines; every face's ring
// still closes along them, nothing crosses, straight kinds keep their
// angles, and the SVG, JSON and OBJ draw the same polylines.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>

#include "g2d/edge_paths.hpp"
#include "g2d/geometry3.hpp"
#include "g2d/json_writer.hpp"
#include "g2d/obj_writer.hpp"
#include "g2d/svg_writer.hpp"
#include "interp/drawing.hpp"
#include "test_helpers.hpp"

using namespace g2d;
using rt::vec2;

namespace {

// Blocks grown from each other's sides; R, U and L bend by up to BEND, D is
// straight (min 0.5, max 1.5).
std::string blocks(const std::string& bend, int steps) {
    return R"g2d(
canvas (0, 0) to (10, 10);
layout angles { clearance = 0.02; bend_segment = 0.1; bend_smooth = 4; }
face Block;
node Corner;
edge R directed { layout { angle = 0; length = 1; left = Block; bend = )g2d" + bend + R"g2d(; } }
edge U directed { layout { angle = radians(90); length = 1; left = Block; bend = )g2d" + bend + R"g2d(; } }
edge L directed { layout { angle = radians(180); length = 1; left = Block; bend = )g2d" + bend + R"g2d(; } }
edge D directed { layout { angle = radians(270); min_length = 0.5; max_length = 1.5; left = Block; } }
axiom { }
limit )g2d" + std::to_string(steps) + R"g2d(;
priority 1 limit 1;
rule Start dpo priority 1 {
    match { }
    produce { a: Corner; b: Corner; c: Corner; d: Corner; a -[R]-> b; b -[U]-> c; c -[L]-> d; d -[D]-> a; }
}
rule Above dpo priority 2 {
    match { d: Corner; c: Corner; top: c -[L]-> d; }
    produce { d: Corner; c: Corner; e: Corner; f: Corner; top; c -[U]-> e; e -[L]-> f; f -[D]-> d; }
}
rule Beside dpo priority 2 {
    match { b: Corner; c: Corner; side: b -[U]-> c; }
    produce { b: Corner; c: Corner; g: Corner; h: Corner; side; b -[R]-> g; g -[U]-> h; h -[L]-> c; }
}
)g2d";
}

struct Seg {
    vec2 a, b;
    rt::EdgeId edge;
    std::size_t k;   // its index along the edge
};

std::vector<vec2> polyline(const rt::Graph& g, rt::EdgeId e) {
    std::vector<vec2> p{g.pos(g.source(e))};
    for (vec2 q : g.edgeBend(e)) p.push_back(q);
    p.push_back(g.pos(g.target(e)));
    return p;
}

std::vector<Seg> segments(const rt::Graph& g) {
    std::vector<Seg> out;
    for (rt::EdgeId e = 0; e < g.edgeCapacity(); ++e) {
        if (!g.edgeAlive(e)) continue;
        const auto p = polyline(g, e);
        for (std::size_t k = 0; k + 1 < p.size(); ++k) out.push_back({p[k], p[k + 1], e, k});
    }
    return out;
}

rt::vec3 v3(vec2 p) { return {p.x, p.y, 0}; }

// No two segments cross or come within `clearance`, except where they meet
// at a shared end (then neither may fold back onto the other).
bool planar(const std::vector<Seg>& s, double clearance) {
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t j = i + 1; j < s.size(); ++j) {
            const Seg &p = s[i], &q = s[j];
            const bool shares = p.a == q.a || p.a == q.b || p.b == q.a || p.b == q.b;
            if (shares) {
                const vec2 at = p.a == q.a || p.a == q.b ? p.a : p.b;
                const vec2 x = p.a == at ? p.b : p.a, y = q.a == at ? q.b : q.a;
                if (rt::segmentsIntersectSharing(v3(at), v3(x), v3(y), clearance * 0.999)) return false;
            } else if (rt::segmentsIntersect(v3(p.a), v3(p.b), v3(q.a), v3(q.b), clearance * 0.999)) {
                return false;
            }
        }
    return true;
}

double signedArea(const std::vector<vec2>& r) {
    double a = 0;
    for (std::size_t i = 0; i < r.size(); ++i) a += r[i].x * r[(i + 1) % r.size()].y - r[(i + 1) % r.size()].x * r[i].y;
    return a / 2;
}

}  // namespace

TEST_CASE("bent edges: polylines from source to target, planar, faces closed along them, straight kinds unmoved",
          "[bend]") {
    for (std::uint64_t seed : {1, 2, 3, 4}) {
        INFO("seed " << seed);
        const test::SnippetRun run = test::runSnippet(blocks("radians(10)", 150), seed, test::verified());
        const rt::Graph& g = run.graph();
        REQUIRE(g.faceCount() >= 6);
        const auto& kinds = run.compiled->program->kinds;
        const int kindD = static_cast<int>(std::find_if(kinds.begin(), kinds.end(), [](const auto& k) { return k.name == "D"; }) - kinds.begin());
        double most = 0;       // the largest turn of a segment from its edge's straight line
        for (rt::EdgeId e = 0; e < g.edgeCapacity(); ++e) {
            if (!g.edgeAlive(e)) continue;
            const vec2 a = g.pos(g.source(e)), b = g.pos(g.target(e));
            if (g.edgeKind(e) == kindD) {   // straight: its nodes stay, so its angle holds
                CHECK(g.edgeBend(e).empty());
                CHECK(a.x == Approx(b.x).margin(1e-9));
                continue;
            }
            // Cut into round(length / 0.1) segments (the drawn length is 1).
            CHECK(g.edgeBend(e).size() == 9);
            const auto p = polyline(g, e);
            for (std::size_t k = 0; k + 1 < p.size(); ++k) {
                const vec2 d = p[k + 1] - p[k], chord = b - a;
                most = std::max(most, std::abs(std::atan2(d.x * chord.y - d.y * chord.x, d.x * chord.x + d.y * chord.y)));
            }
        }
        CHECK(most > 0.05);   // they do bend
        CHECK(planar(segments(g), 0.02));
        CHECK(run.derivation.bendsReduced == 0);
        // Each face's ring runs along its edges' polylines and still encloses
        // it counter-clockwise with a simple boundary.
        for (rt::FaceId f = 0; f < g.faceCapacity(); ++f) {
            if (!g.faceAlive(f)) continue;
            std::vector<rt::NodeId> ring;
            rt::CornerId c = g.firstCorner(f);
            for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) ring.push_back(g.cornerNode(c));
            const std::vector<vec2> drawn = rt::bentRing(g, ring);
            std::size_t expected = ring.size();
            for (std::size_t i = 0; i < ring.size(); ++i) {
                const rt::RingStep s = rt::ringStep(g, ring[i], ring[(i + 1) % ring.size()]);
                REQUIRE(s.edge != rt::kNoId);
                expected += g.edgeBend(s.edge).size();
            }
            CHECK(drawn.size() == expected);
            CHECK(signedArea(drawn) > 0);
        }
    }
}

TEST_CASE("bending is a function of the seed, and a grammar without `bend` draws exactly as before", "[bend]") {
    const test::SnippetRun a = test::runSnippet(blocks("radians(10)", 120), 7, test::verified());
    const test::SnippetRun b = test::runSnippet(blocks("radians(10)", 120), 7, test::verified());
    const test::SnippetRun flat = test::runSnippet(blocks("0", 120), 7, test::verified());
    REQUIRE(a.graph().nodeCount() == flat.graph().nodeCount());
    // Nodes at a straight edge (D) stay exactly where the run without bends
    // has them; nodes whose edges all bend follow their edges.
    std::vector<char> atStraight(a.graph().nodeCapacity(), 0);
    for (rt::EdgeId e = 0; e < a.graph().edgeCapacity(); ++e)
        if (a.graph().edgeAlive(e) && a.graph().edgeBend(e).empty()) atStraight[a.graph().source(e)] = atStraight[a.graph().target(e)] = 1;
    bool moved = false;
    for (rt::NodeId n = 0; n < a.graph().nodeCapacity(); ++n) {
        if (!a.graph().nodeAlive(n)) continue;
        CHECK(a.graph().pos(n) == b.graph().pos(n));
        if (atStraight[n]) CHECK(a.graph().pos(n) == flat.graph().pos(n));
        moved = moved || a.graph().pos(n) != flat.graph().pos(n);
    }
    CHECK(moved);   // nodes whose edges all bend follow them
    CHECK_FALSE(flat.graph().hasBends());
    for (rt::EdgeId e = 0; e < a.graph().edgeCapacity(); ++e)
        if (a.graph().edgeAlive(e)) CHECK(std::equal(a.graph().edgeBend(e).begin(), a.graph().edgeBend(e).end(), b.graph().edgeBend(e).begin()));
}

TEST_CASE("bends too strong to stay planar are cut and counted, and the drawing stays planar", "[bend]") {
    long long reduced = 0;
    for (std::uint64_t seed : {1, 2, 3}) {
        INFO("seed " << seed);
        const test::SnippetRun run = test::runSnippet(blocks("radians(85)", 150), seed, test::verified());
        CHECK(planar(segments(run.graph()), 0.02));
        reduced += run.derivation.bendsReduced;
    }
    CHECK(reduced > 0);
}

TEST_CASE("SVG, JSON and OBJ draw the bends: polylines, bend arrays, and faces through the bend points", "[bend]") {
    const test::SnippetRun run = test::runSnippet(blocks("radians(10)", 60), 3, test::verified());
    const rt::Graph& g = run.graph();
    const ir::Program& prog = *run.compiled->program;
    std::size_t bends = 0, edges = 0;
    for (rt::EdgeId e = 0; e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) ++edges, bends += g.edgeBend(e).empty() ? 0 : 1;
    REQUIRE(bends > 0);
    const std::string svg = rt::writeSvg(run.grammar->drawItems(), {});
    std::size_t polylines = 0;
    for (std::size_t at = svg.find("<polyline points=\""); at != std::string::npos; at = svg.find("<polyline points=\"", at + 1)) ++polylines;
    CHECK(polylines == bends);
    const std::string json = rt::writeJson(g, interp::jsonSchema(prog), {});
    std::size_t arrays = 0;
    for (std::size_t at = json.find("\"bend\": [["); at != std::string::npos; at = json.find("\"bend\": [[", at + 1)) ++arrays;
    CHECK(arrays == bends);
    // OBJ: a vertex per node and per bend point; each edge an `l` through its points.
    const std::string obj = rt::writeObj(g, interp::jsonSchema(prog));
    std::istringstream in(obj);
    std::string line;
    std::size_t vertices = 0, lines = 0, longest = 0;
    while (std::getline(in, line)) {
        if (line.rfind("v ", 0) == 0) ++vertices;
        if (line.rfind("l ", 0) == 0) {
            ++lines;
            longest = std::max<std::size_t>(longest, static_cast<std::size_t>(std::count(line.begin(), line.end(), ' ')));
        }
    }
    std::size_t points = g.nodeCount();
    for (rt::EdgeId e = 0; e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) points += g.edgeBend(e).size();
    CHECK(vertices == points);
    CHECK(lines == edges);
    CHECK(longest == 11);   // source, 9 bend points, target
}
