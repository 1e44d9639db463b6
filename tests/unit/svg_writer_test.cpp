// The SVG writer: one element per graph element, chosen by the `tag` style.
#include <catch2/catch.hpp>

#include "g2d/svg_writer.hpp"

using namespace g2d::rt;

namespace {

DrawItem node(std::uint32_t id, vec2 p, std::vector<StyleOverride> props) {
    DrawItem it;
    it.id = id;
    it.a = p;
    it.props = std::move(props);
    return it;
}

DrawItem edge(std::uint32_t id, vec2 a, vec2 b, std::vector<StyleOverride> props) {
    DrawItem it = node(id, a, std::move(props));
    it.cls = ElemClass::Edge;
    it.b = b;
    return it;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("default drawing: nodes as circles, edges as lines, y up, fitted viewBox", "[svg]") {
    const std::string svg = writeSvg({node(0, {0, 0}, {}), node(1, {2, 1}, {}), edge(0, {0, 0}, {2, 1}, {})}, {});
    CHECK(contains(svg, "<line x1=\"0\" y1=\"0\" x2=\"2\" y2=\"1\" stroke=\"black\" stroke-width=\"0.05\"/>"));
    CHECK(contains(svg, "<circle cx=\"2\" cy=\"1\" r=\"0.1\" fill=\"none\" stroke=\"black\" stroke-width=\"0.02\"/>"));
    CHECK(contains(svg, "<g transform=\"scale(1 -1)\">"));
    // The box of the circles (r 0.1) padded by the widest stroke and 2 %: x from -0.1 - 0.094.
    CHECK(contains(svg, "viewBox=\"-0.194 -1.194 2.388 1.388\""));
    CHECK(contains(svg, "width=\"2.388cm\" height=\"1.388cm\""));
    // Edges are drawn before nodes.
    CHECK(svg.find("<line") < svg.find("<circle"));
}

TEST_CASE("tags and their special properties", "[svg]") {
    const std::string svg = writeSvg(
        {node(0, {1, 2}, {{"tag", std::string("rect")}, {"width", 2.0}, {"height", 1.0}, {"rotate", 30.0}, {"fill", std::string("red")}}),
         node(1, {0, 0}, {{"tag", std::string("path")}, {"d", std::string("M 0 0 L 1 1")}, {"stroke_width", 0.2}}),
         node(2, {5, 5}, {{"tag", std::string("image")}, {"href", std::string("a&b.png")}, {"width", 2.0}, {"height", 4.0}, {"rotate", 90.0}, {"filter", std::string("brown")}}),
         node(3, {1, 1}, {{"tag", std::string("text")}, {"text", std::string("x < y")}}),
         node(4, {9, 9}, {{"tag", std::string("none")}}),
         edge(0, {0, 0}, {1, 0}, {{"arrow", true}, {"stroke_dasharray", std::string("0.1 0.1")}})},
        {"<filter id='brown'/>"});
    CHECK(contains(svg, "<rect x=\"0\" y=\"1.5\" width=\"2\" height=\"1\" transform=\"rotate(30 1 2)\" fill=\"red\"/>"));
    CHECK(contains(svg, "<path d=\"M 0 0 L 1 1\" fill=\"none\" stroke=\"black\" stroke-width=\"0.2\"/>"));
    CHECK(contains(svg, "<image href=\"a&amp;b.png\" x=\"-1\" y=\"-2\" width=\"2\" height=\"4\" "
                        "transform=\"translate(5 5) rotate(90) scale(1 -1)\" filter=\"url(#brown)\"/>"));
    CHECK(contains(svg, ">x &lt; y</text>"));
    CHECK_FALSE(contains(svg, "9\""));  // `none` draws nothing
    CHECK(contains(svg, "marker-end=\"url(#g2d-arrow)\""));
    CHECK(contains(svg, "stroke-dasharray=\"0.1 0.1\""));
    CHECK(contains(svg, "<defs>\n<marker id=\"g2d-arrow\""));
    CHECK(contains(svg, "<filter id='brown'/>\n</defs>"));
}

TEST_CASE("z orders the drawing", "[svg]") {
    const std::string svg = writeSvg({node(0, {0, 0}, {{"z", 2LL}, {"fill", std::string("top")}}),
                                      node(1, {1, 1}, {{"fill", std::string("bottom")}})}, {});
    CHECK(svg.find("bottom") < svg.find("top"));
}

TEST_CASE("an empty graph is a valid, tiny drawing", "[svg]") {
    const std::string svg = writeSvg({}, {});
    CHECK(contains(svg, "viewBox=\"0 -1 1 1\""));
}

TEST_CASE("rectangles and images are measured by their corners, turned or not", "[svg]") {
    // A 10 × 1 lot: 10 wide and 1 high (not a 10.05-wide square round its
    // half-diagonal), padded by the node stroke (0.02) and 2 % of 10.
    const std::string lot = writeSvg({node(0, {0, 0}, {{"tag", std::string("rect")}, {"width", 10.0}, {"height", 1.0}})}, {});
    CHECK(contains(lot, "viewBox=\"-5.22 -0.72 10.44 1.44\""));
    // Turned a quarter: 1 wide and 10 high.
    const std::string upright =
        writeSvg({node(0, {0, 0}, {{"tag", std::string("rect")}, {"width", 10.0}, {"height", 1.0}, {"rotate", 90.0}})}, {});
    CHECK(contains(upright, "viewBox=\"-0.72 -5.22 1.44 10.44\""));
    // An image 2 × 4 turned by 30°: half-extents (2 cos 30° + 4 sin 30°) / 2 and (2 sin 30° + 4 cos 30°) / 2.
    const std::string image = writeSvg(
        {node(0, {0, 0}, {{"tag", std::string("image")}, {"href", std::string("a.png")}, {"width", 2.0}, {"height", 4.0}, {"rotate", 30.0}})},
        {});
    CHECK(contains(image, "viewBox=\"-1.975308 -2.341333 3.950616 4.682666\""));
}
