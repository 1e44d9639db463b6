// The --view page (view_page.hpp): which elements its model shows and in
// which colours and sizes, positions with z, and a page that is the same
// bytes for the same model and that nothing in the model can break out of.
// tests/view/view_page_test.sh renders it.
#include <catch2/catch.hpp>

#include <cmath>

#include "g2d/view_page.hpp"

using namespace g2d::rt;

namespace {

DrawItem item(ElemClass cls, std::uint32_t id, std::vector<StyleOverride> props) {
    DrawItem it;
    it.cls = cls;
    it.id = id;
    it.props = std::move(props);
    return it;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("view model: nodes, edges and faces as the styles draw them, in 3D", "[view]") {
    // Kinds: 0 node, 1 edge, 2 face.
    Graph g({KindInfo{ElemClass::Node, false}, KindInfo{ElemClass::Edge, false}, KindInfo{ElemClass::Face, false}});
    const NodeId gone = g.addNode(0, {9, 9}, 0);
    const NodeId a = g.addNode(0, {0, 0}, 0), b = g.addNode(0, {3, 0}, 0), c = g.addNode(0, {0, 4}, 0),
                 d = g.addNode(0, {1, 1}, 0);
    g.removeNode(gone);   // indices skip dead nodes
    g.setZ(d, 12);
    const EdgeId ab = g.addEdge(1, a, b, 0), bc = g.addEdge(1, b, c, 0), ca = g.addEdge(1, c, a, 0);
    const NodeId abc[] = {a, b, c}, abd[] = {a, b, d};
    const FaceId shown = g.addFace(2, abc, 0), hidden = g.addFace(2, abd, 0);
    const std::vector<DrawItem> items = {
        item(ElemClass::Face, shown, {{"fill", std::string("hsl(10, 50%, 50%)")}, {"fill_opacity", 0.4}}),
        item(ElemClass::Face, hidden, {{"tag", std::string("none")}, {"fill", std::string("red")}}),
        item(ElemClass::Edge, ab, {{"stroke", std::string("#d62728")}}),
        item(ElemClass::Edge, bc, {{"tag", std::string("none")}}),
        item(ElemClass::Edge, ca, {}),
        item(ElemClass::Node, a, {{"fill", std::string("#123456")}, {"r", 0.25}}),
        item(ElemClass::Node, b, {}),
        item(ElemClass::Node, c, {{"tag", std::string("none")}, {"fill", std::string("blue")}}),
        item(ElemClass::Node, d, {{"tag", std::string("rect")}, {"stroke", std::string("none")}, {"fill", std::string("green")}}),
    };
    const ViewModel m = viewModelOf(g, items, "t.g2d");
    CHECK(m.title == "t.g2d");
    REQUIRE(m.nodes.size() == 4);
    CHECK(m.nodes[0].pos == std::array<double, 3>{0, 0, 0});
    CHECK(m.nodes[3].pos == std::array<double, 3>{1, 1, 12});
    // r as given; else 0.6 % of the diagonal (3, 4, 12: 13); fill, else stroke (black).
    CHECK((m.nodes[0].radius == 0.25 && m.nodes[0].color == "#123456"));
    CHECK((m.nodes[1].radius == Approx(0.078) && m.nodes[1].color == "black"));
    CHECK((m.nodes[2].radius == 0 && m.nodes[2].color.empty()));   // tag none: a corner, not drawn
    CHECK((m.nodes[3].radius == Approx(0.078) && m.nodes[3].color == "green"));
    REQUIRE(m.edges.size() == 2);
    CHECK((m.edges[0].a == 0 && m.edges[0].b == 1 && m.edges[0].color == "#d62728"));
    CHECK((m.edges[1].a == 2 && m.edges[1].b == 0 && m.edges[1].color == "black"));
    REQUIRE(m.faces.size() == 1);
    CHECK(m.faces[0].id == shown);
    CHECK(m.faces[0].points == std::vector<std::array<double, 3>>{{0, 0, 0}, {3, 0, 0}, {0, 4, 0}});
    REQUIRE(m.faces[0].triangles.size() == 1);
    const auto t = m.faces[0].triangles[0];   // 0 1 2 from any corner: the face's way round
    CHECK((t[1] == (t[0] + 1) % 3 && t[2] == (t[1] + 1) % 3));
    CHECK(m.faces[0].color == "hsl(10, 50%, 50%)");
    CHECK(m.faces[0].opacity == 0.4);
    // The graph's counts, drawn or not.
    CHECK((m.graphNodes == 4 && m.graphEdges == 3 && m.graphFaces == 2));
}

TEST_CASE("view model: a non-convex face as triangles in its plane, thick edges, an undrawable face an error", "[view]") {
    Graph g({KindInfo{ElemClass::Node, false}, KindInfo{ElemClass::Edge, false}, KindInfo{ElemClass::Face, false}});
    // An L in the plane x = 1, corners counter-clockwise seen from +x: a fan
    // from the first corner would cover the notch.
    const std::vector<vec3> at = {{1, 0, 0}, {1, 2, 0}, {1, 2, 1}, {1, 1, 1}, {1, 1, 2}, {1, 0, 2}};
    std::vector<NodeId> l;
    for (const vec3& p : at) {
        l.push_back(g.addNode(0, {p.x, p.y}, 0));
        g.setZ(l.back(), p.z);
    }
    g.setRadius(l[0], 0.2);
    g.setRadius(l[1], 0.1);
    const EdgeId thick = g.addEdge(1, l[0], l[1], 0);
    const FaceId f = g.addFace(2, l, 0);
    const std::vector<DrawItem> items = {item(ElemClass::Face, f, {}), item(ElemClass::Edge, thick, {})};
    const ViewModel m = viewModelOf(g, items, "l.g2d", {"P", "E", "Wall"});
    REQUIRE(m.edges.size() == 1);
    CHECK(m.edges[0].radius == Approx(0.15));
    REQUIRE(m.faces.size() == 1);
    const ViewFace& v = m.faces[0];
    REQUIRE(v.triangles.size() == 4);
    double area = 0;
    for (const auto& t : v.triangles) {
        // (b - a) x (c - a) along +x: each triangle runs the face's way round.
        const auto& a = v.points[t[0]], &b = v.points[t[1]], &c = v.points[t[2]];
        const double nx = (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]);
        CHECK(nx > 0);
        area += nx / 2;
    }
    CHECK(area == Approx(3));
    // Corners on one line: no page, a message naming the face.
    const NodeId p = g.addNode(0, {0, 0}, 0), q = g.addNode(0, {1, 0}, 0), r = g.addNode(0, {2, 0}, 0);
    const NodeId line[] = {p, q, r};
    const FaceId flat = g.addFace(2, line, 0);
    const std::vector<DrawItem> both = {item(ElemClass::Face, f, {}), item(ElemClass::Face, flat, {})};
    CHECK_THROWS_WITH(viewModelOf(g, both, "l.g2d", {"P", "E", "Wall"}),
                      "face 1 (Wall, corners 6 7 8) cannot be drawn as triangles: its corners lie on one line, so it has no area");
}

TEST_CASE("view page: the model inline, colours once each, nothing ends a script early", "[view]") {
    ViewModel m;
    m.title = "a</script><b>&\"";
    m.nodes = {{{0, 0.1, -2.5}, 0.05, "red"}, {{1, 0, 0}, 0, ""}, {{0, 1, 1e-7}, 0.05, "red"}};
    m.edges = {{0, 1, "red"}};
    m.edges[0].radius = 0.25;
    m.faces = {{7, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0.5}}, {{0, 1, 2}}, "#00ff00", 0.5}};
    m.graphNodes = 3;
    m.graphEdges = 2;
    m.graphFaces = 1;
    m.home = vec3{1, -2, 1.5};
    const std::string page = writeViewPage(m);
    CHECK(page == writeViewPage(m));
    CHECK(contains(page, "<title>a&lt;/script&gt;&lt;b&gt;&amp;&quot; — g2d view</title>"));
    CHECK(contains(page, "{\"title\":\"a\\u003c/script>\\u003cb>&\\\"\",\n\"home\":[1,-2,1.5],\n"
                         "\"counts\":{\"nodes\":3,\"edges\":2,\"faces\":1},\n\"colors\":[\"red\",\"#00ff00\"],\n"
                         "\"nodes\":[\n[0,0.1,-2.5,0.05,0],\n[1,0,0,0,-1],\n[0,1,1e-07,0.05,0]],\n"
                         "\"edges\":[\n[0,1,0,0.25]],\n\"faces\":[\n[7,1,[0,0,0,1,0,0,0,1,0.5],[0,1,2]]],\n\"faceAlphas\":[0.5]}</script>"));
    // The graph's counts; fewer drawn are said (node 1 has radius 0).
    CHECK(contains(page, "3 nodes (2 drawn), 2 edges (1 drawn), 1 face"));
    // The model's script element, then the embedded bundle's, and no other.
    CHECK(page.find("</script>") != page.rfind("</script>"));
    CHECK(page.find("<script", page.find("<script", page.find("<script") + 1) + 1) == std::string::npos);
    CHECK(contains(page, "OrbitControls"));
    m.nodes[0].pos[1] = std::nan("");
    CHECK_THROWS_WITH(writeViewPage(m), "the model has a non-finite number (nan)");
}
