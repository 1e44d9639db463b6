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
    CHECK(m.faces[0].corners == std::vector<std::uint32_t>{0, 1, 2});
    CHECK(m.faces[0].color == "hsl(10, 50%, 50%)");
    CHECK(m.faces[0].opacity == 0.4);
}

TEST_CASE("view page: the model inline, colours once each, nothing ends a script early", "[view]") {
    ViewModel m;
    m.title = "a</script><b>&\"";
    m.nodes = {{{0, 0.1, -2.5}, 0.05, "red"}, {{1, 0, 0}, 0, ""}, {{0, 1, 1e-7}, 0.05, "red"}};
    m.edges = {{0, 1, "red"}};
    m.faces = {{{0, 1, 2}, "#00ff00", 0.5}};
    m.home = vec3{1, -2, 1.5};
    const std::string page = writeViewPage(m);
    CHECK(page == writeViewPage(m));
    CHECK(contains(page, "<title>a&lt;/script&gt;&lt;b&gt;&amp;&quot; — g2d view</title>"));
    CHECK(contains(page, "{\"title\":\"a\\u003c/script>\\u003cb>&\\\"\",\n\"home\":[1,-2,1.5],\n\"colors\":[\"red\",\"#00ff00\"],\n"
                         "\"nodes\":[\n[0,0.1,-2.5,0.05,0],\n[1,0,0,0,-1],\n[0,1,1e-07,0.05,0]],\n"
                         "\"edges\":[\n[0,1,0]],\n\"faces\":[\n[1,0,1,2]],\n\"faceAlphas\":[0.5]}</script>"));
    CHECK(contains(page, "3 nodes, 1 edge, 1 face"));
    // The model's script element, then the embedded bundle's, and no other.
    CHECK(page.find("</script>") != page.rfind("</script>"));
    CHECK(page.find("<script", page.find("<script", page.find("<script") + 1) + 1) == std::string::npos);
    CHECK(contains(page, "OrbitControls"));
    m.nodes[0].pos[1] = std::nan("");
    CHECK_THROWS_WITH(writeViewPage(m), "the model has a non-finite number (nan)");
}
