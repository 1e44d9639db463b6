// Faces with holes (issue #44): the triangles OBJ gets for them
// (polygon_triangles.hpp) cover the ring exactly, a `layout angles` run
// that leaves an island in a face writes the face with its hole in SVG,
// JSON and OBJ, and the graph drops holes with their face or node.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <random>
#include <regex>
#include <sstream>

#include "g2d/json_writer.hpp"
#include "g2d/obj_writer.hpp"
#include "g2d/polygon_triangles.hpp"
#include "g2d/svg_writer.hpp"
#include "interp/drawing.hpp"
#include "test_helpers.hpp"

using namespace g2d;
using rt::vec2;

namespace {

using Ring = std::vector<int>;
using Triangles = std::vector<std::array<int, 3>>;

double twiceArea(vec2 a, vec2 b, vec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

double ringArea(const std::vector<vec2>& p, const Ring& r) {
    double a = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
        const vec2 u = p[static_cast<std::size_t>(r[i])], v = p[static_cast<std::size_t>(r[(i + 1) % r.size()])];
        a += u.x * v.y - u.y * v.x;
    }
    return a / 2;
}

bool inRing(const std::vector<vec2>& p, const Ring& r, vec2 q) {
    bool in = false;
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
        const vec2 a = p[static_cast<std::size_t>(r[i])], b = p[static_cast<std::size_t>(r[j])];
        if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
    return in;
}

bool inTriangle(vec2 a, vec2 b, vec2 c, vec2 q) { return twiceArea(a, b, q) > 0 && twiceArea(b, c, q) > 0 && twiceArea(c, a, q) > 0; }

// The triangles are counter-clockwise, add up to the outer ring's area less
// the holes', and every point of a fine grid (off every corner and side) in
// the polygon lies in exactly one of them, every other in none.
void checkCover(const std::vector<vec2>& p, const Ring& outer, const std::vector<Ring>& holes) {
    const Triangles t = rt::triangulate(p, outer, holes);
    double expected = ringArea(p, outer), sum = 0;
    for (const Ring& h : holes) expected += ringArea(p, h);   // negative: clockwise
    for (const auto& [a, b, c] : t) {
        const double area = twiceArea(p[static_cast<std::size_t>(a)], p[static_cast<std::size_t>(b)], p[static_cast<std::size_t>(c)]) / 2;
        CHECK(area > 0);
        sum += area;
    }
    CHECK(sum == Approx(expected).epsilon(1e-12));
    vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
    for (int v : outer) {
        lo = {std::min(lo.x, p[static_cast<std::size_t>(v)].x), std::min(lo.y, p[static_cast<std::size_t>(v)].y)};
        hi = {std::max(hi.x, p[static_cast<std::size_t>(v)].x), std::max(hi.y, p[static_cast<std::size_t>(v)].y)};
    }
    int wrong = 0;
    for (double x = lo.x + 0.0123; x < hi.x; x += 0.0917)
        for (double y = lo.y + 0.0071; y < hi.y; y += 0.0833) {
            const vec2 q{x, y};
            bool inside = inRing(p, outer, q);
            for (const Ring& h : holes) inside = inside && !inRing(p, h, q);
            int covering = 0;
            for (const auto& [a, b, c] : t)
                covering += inTriangle(p[static_cast<std::size_t>(a)], p[static_cast<std::size_t>(b)], p[static_cast<std::size_t>(c)], q);
            if (covering != (inside ? 1 : 0) && wrong++ == 0) UNSCOPED_INFO("first wrong at (" << x << ", " << y << "): " << covering << " triangles");
        }
    CHECK(wrong == 0);
}

}  // namespace

TEST_CASE("triangles cover a square with a square hole exactly", "[face-holes]") {
    const std::vector<vec2> p{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {4, 6}, {6, 6}, {6, 4}};
    checkCover(p, {0, 1, 2, 3}, {{4, 5, 6, 7}});
    CHECK(rt::triangulate(p, {0, 1, 2, 3}, {{4, 5, 6, 7}}).size() == 8);
}

TEST_CASE("triangles cover a concave ring with collinear corners and several holes", "[face-holes]") {
    // A comb: a base 0..9 x 0..2 with teeth at x 0-2, 4-6, 8-9 up to y 6,
    // collinear corners along the base; a hole in each wide tooth and two
    // in the base.
    const std::vector<vec2> p{{0, 0}, {3, 0}, {6, 0}, {9, 0}, {9, 6}, {8, 6}, {8, 2}, {6, 2}, {6, 6}, {4, 6}, {4, 2}, {2, 2}, {2, 6}, {0, 6},
                              // holes (clockwise): in tooth 1, in tooth 2, two in the base
                              {0.5, 3}, {0.5, 5}, {1.5, 5}, {1.5, 3}, {4.5, 3}, {4.5, 4}, {5.5, 4}, {5.5, 3},
                              {1, 0.5}, {1, 1.5}, {3, 1.5}, {3, 0.5}, {3.3, 1}, {3.8, 1}, {3.55, 0.4}};
    const Ring outer{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13};
    checkCover(p, outer, {{14, 15, 16, 17}, {18, 19, 20, 21}, {22, 23, 24, 25}, {26, 27, 28}});
}

TEST_CASE("a hole touching the outer ring at a corner is covered around", "[face-holes]") {
    const std::vector<vec2> p{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 3}, {3, 2}};
    checkCover(p, {0, 1, 2, 3}, {{2, 5, 4}});
}

TEST_CASE("two holes sharing a corner are covered around", "[face-holes]") {
    // Two islands touching at a corner are one component, whose outside
    // traceFaces cuts into two clockwise rings sharing that node.
    const std::vector<vec2> p{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {5, 5}, {4, 5}, {4, 4}, {5, 4}, {5, 6}, {6, 6}, {6, 5}};
    checkCover(p, {0, 1, 2, 3}, {{4, 7, 6, 5}, {4, 8, 9, 10}});
    checkCover(p, {0, 1, 2, 3}, {{4, 8, 9, 10}, {4, 7, 6, 5}});
}

TEST_CASE("triangles cover a square with holes in rows, where rays from one hole run along others", "[face-holes]") {
    // Squares, diamonds and triangles on a grid, in 300 arrangements: their
    // corners share rows and columns, the degenerate case of bridging that
    // axis-aligned drawings are full of.
    for (unsigned seed = 0; seed < 300; ++seed) {
        INFO("seed " << seed);
        std::mt19937 rng(seed);
        std::vector<vec2> p{{0, 0}, {8, 0}, {8, 8}, {0, 8}};
        std::vector<Ring> holes;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                const double x = 2 * i + 0.5, y = 2 * j + 0.5;
                const int v = static_cast<int>(p.size());
                switch (rng() % 4) {
                case 0: break;
                case 1: p.insert(p.end(), {{x, y}, {x, y + 1}, {x + 1, y + 1}, {x + 1, y}}); holes.push_back({v, v + 1, v + 2, v + 3}); break;
                case 2: p.insert(p.end(), {{x + 0.5, y}, {x, y + 0.5}, {x + 0.5, y + 1}, {x + 1, y + 0.5}}); holes.push_back({v, v + 1, v + 2, v + 3}); break;
                default: p.insert(p.end(), {{x, y}, {x + 0.5, y + 1}, {x + 1, y}}); holes.push_back({v, v + 1, v + 2}); break;
                }
            }
        checkCover(p, {0, 1, 2, 3}, holes);
    }
}

TEST_CASE("triangles cover a concave ring without holes, and fewer than 3 corners give none", "[face-holes]") {
    const std::vector<vec2> p{{0, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}};
    checkCover(p, {0, 1, 2, 3, 4}, {});
    CHECK(rt::triangulate(p, {0, 1}, {}).empty());
}

namespace {

// A 10-square room (its canvas leaves 2 units of play) with a 2-square
// pond drawn in the same step: a separate component, so an island.
const char* kIsland = R"g2d(
layout angles { canvas_min = (0, 0); canvas_max = (12, 12); }
face Room { style { fill = "#c8dcf0"; } }
face Pond { style { fill = "#f0c8c8"; } }
node Corner { style { tag = "none"; } }
edge R directed { layout { angle = 0; length = 10; left = Room; } }
edge U directed { layout { angle = radians(90); length = 10; left = Room; } }
edge L directed { layout { angle = radians(180); length = 10; left = Room; } }
edge D directed { layout { angle = radians(270); length = 10; left = Room; } }
edge IR directed { layout { angle = 0; length = 2; left = Pond; right = Room; } }
edge IU directed { layout { angle = radians(90); length = 2; left = Pond; right = Room; } }
edge IL directed { layout { angle = radians(180); length = 2; left = Pond; right = Room; } }
edge ID directed { layout { angle = radians(270); length = 2; left = Pond; right = Room; } }
axiom { }
limit 5;
rule Scene dpo {
    match { }
    produce {
        a: Corner; b: Corner; c: Corner; d: Corner;
        a -[R]-> b; b -[U]-> c; c -[L]-> d; d -[D]-> a;
        p: Corner; q: Corner; r: Corner; s: Corner;
        p -[IR]-> q; q -[IU]-> r; r -[IL]-> s; s -[ID]-> p;
    }
}
)g2d";

std::vector<double> numbers(const std::string& text) {
    std::vector<double> out;
    static const std::regex number(R"(-?[0-9][0-9.e+-]*)");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it) out.push_back(std::stod(it->str()));
    return out;
}

}  // namespace

TEST_CASE("an island leaves a hole in its face: SVG path, JSON hole cycle, OBJ triangles", "[face-holes]") {
    for (std::uint64_t seed : {1, 2, 3}) {
        INFO("seed " << seed);
        const test::SnippetRun run = test::runSnippet(kIsland, seed, test::verified());
        const ir::Program& prog = *run.compiled->program;
        const rt::Graph& g = run.graph();
        REQUIRE(g.faceCount() == 2);
        // The graph: the room (face 0) has the pond's outside as its hole, clockwise.
        const rt::FaceId room = 0, pond = 1;
        REQUIRE(g.faceHoles(room).size() == 1);
        CHECK(g.faceHoles(pond).empty());
        const std::vector<rt::NodeId>& hole = g.faceHoles(room)[0];
        std::vector<vec2> at;
        for (rt::NodeId n = 0; n < g.nodeCapacity(); ++n) at.push_back(g.pos(n));
        Ring holeRing(hole.begin(), hole.end());
        CHECK(ringArea(at, holeRing) == Approx(-4));
        std::vector<rt::NodeId> pondCorners;
        rt::CornerId c = g.firstCorner(pond);
        for (int i = 0; i < g.cornerCount(pond); ++i, c = g.nextCorner(c)) pondCorners.push_back(g.cornerNode(c));
        CHECK(std::is_permutation(hole.begin(), hole.end(), pondCorners.begin(), pondCorners.end()));

        // SVG: the room is one path, its ring then its hole, filled evenodd.
        const std::string svg = rt::writeSvg(run.grammar->drawItems(), {});
        static const std::regex path(R"re(<path d="M([^"]*) Z M([^"]*) Z"([^>]*)/>)re");
        std::smatch m;
        REQUIRE(std::regex_search(svg, m, path));
        CHECK(m[3].str().find("fill-rule=\"evenodd\"") != std::string::npos);
        CHECK(m[3].str().find("fill=\"#c8dcf0\"") != std::string::npos);
        const std::vector<double> svgHole = numbers(m[2].str());
        REQUIRE(svgHole.size() == 8);
        for (std::size_t i = 0; i < 4; ++i) {
            CHECK(svgHole[2 * i] == g.pos(hole[i]).x);
            CHECK(svgHole[2 * i + 1] == g.pos(hole[i]).y);
        }
        CHECK(svg.find("<polygon") != std::string::npos);   // the pond, as any face

        // JSON: the room's hole cycle as node ids; the pond has none.
        const std::string json = rt::writeJson(g, interp::jsonSchema(prog), {});
        std::ostringstream holes;
        holes << "\"holes\": [[" << hole[0] << ", " << hole[1] << ", " << hole[2] << ", " << hole[3] << "]]";
        CHECK(json.find(holes.str()) != std::string::npos);
        CHECK(json.find("\"holes\"") == json.rfind("\"holes\""));

        // OBJ: the room as triangles that add up to its ring less the hole
        // (100 - 4), each counter-clockwise; the pond one quad.
        const std::string obj = rt::writeObj(g, interp::jsonSchema(prog));
        std::istringstream in(obj);
        std::vector<vec2> v;
        std::map<std::string, std::vector<std::vector<int>>> faces;
        std::string line, group;
        while (std::getline(in, line)) {
            std::istringstream fields(line);
            std::string tag;
            fields >> tag;
            if (tag == "v") {
                double x = 0, y = 0;
                fields >> x >> y;
                v.push_back({x, y});
            } else if (tag == "g") {
                fields >> group;
            } else if (tag == "f") {
                faces[group].emplace_back();
                for (std::string corner; fields >> corner;) faces[group].back().push_back(std::stoi(corner) - 1);   // `v//n`
            }
        }
        REQUIRE(faces["Room"].size() == 8);
        double sum = 0;
        for (const auto& t : faces["Room"]) {
            REQUIRE(t.size() == 3);
            const double a = twiceArea(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])], v[static_cast<std::size_t>(t[2])]) / 2;
            CHECK(a > 0);
            sum += a;
        }
        CHECK(sum == Approx(96).epsilon(1e-12));
        REQUIRE(faces["Pond"].size() == 1);
        CHECK(faces["Pond"][0].size() == 4);
    }
}

TEST_CASE("a face's holes go with the face, and a ring with its node", "[face-holes]") {
    rt::Graph g({rt::KindInfo{rt::ElemClass::Node, false}, rt::KindInfo{rt::ElemClass::Face, false}});
    std::vector<rt::NodeId> n;
    for (int i = 0; i < 11; ++i) n.push_back(g.addNode(0, {static_cast<double>(i), static_cast<double>(i * i % 7)}, 0));
    const rt::FaceId f = g.addFace(1, std::vector<rt::NodeId>{n[0], n[1], n[2]}, 0);
    const rt::FaceId other = g.addFace(1, std::vector<rt::NodeId>{n[8], n[9], n[10]}, 0);
    CHECK(g.faceHoles(f).empty());
    g.setFaceHoles(f, {{n[3], n[4], n[5]}, {n[5], n[6], n[7]}});
    REQUIRE(g.faceHoles(f).size() == 2);
    CHECK(g.faceHoles(other).empty());
    g.removeNode(n[3]);   // the first ring's node: that ring goes, the other stays
    REQUIRE(g.faceHoles(f).size() == 1);
    CHECK(g.faceHoles(f)[0] == std::vector<rt::NodeId>{n[5], n[6], n[7]});
    g.removeFace(f);
    CHECK(g.faceHoles(f).empty());
    CHECK_THROWS(g.setFaceHoles(f, {{n[5], n[6], n[7]}}));
}
