// Decorations (Merrell's Appendix B, decorations.hpp): where `decor_*`
// places its images or shapes on nodes, along edges (bent ones too) and
// over faces, and how the SVG writes them.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "g2d/decorations.hpp"
#include "g2d/svg_writer.hpp"

using namespace g2d::rt;

namespace {

DrawItem item(ElemClass cls, std::uint32_t id, std::vector<StyleOverride> props) {
    DrawItem it;
    it.cls = cls;
    it.id = id;
    it.props = std::move(props);
    return it;
}

DrawItem square(double lo, double hi, std::vector<StyleOverride> props) {
    DrawItem f = item(ElemClass::Face, 0, std::move(props));
    f.corners = {{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
    f.a = {(lo + hi) / 2, (lo + hi) / 2};
    return f;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::size_t count(const std::string& s, const std::string& part) {
    std::size_t n = 0;
    for (std::size_t at = s.find(part); at != std::string::npos; at = s.find(part, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("an edge's decoration is tiled along it: round(L / every) tiles, turned with it, offset to its left", "[decor]") {
    DrawItem e = item(ElemClass::Edge, 0, {{"decor_tag", std::string("rect")}, {"decor_every", 0.3}, {"decor_offset", 0.1}});
    e.a = {1, 1};
    e.b = {1, 2};   // up: 90 degrees; length 1, so round(1 / 0.3) = 3 tiles of 1/3
    const std::vector<Placement> p = decorPlacements(e);
    REQUIRE(p.size() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
        CHECK(p[k].centre.x == Approx(0.9));   // the left of "up" is -x
        CHECK(p[k].centre.y == Approx(1 + (k + 0.5) / 3));
        CHECK(p[k].degrees == Approx(90));
        CHECK(p[k].width == Approx(1.0 / 3));
        CHECK(p[k].height == Approx(0.2));
    }
    // Without `decor_every`, one tile the edge's length.
    e.props = {{"decor_tag", std::string("rect")}, {"decor_width", 0.1}};
    REQUIRE(decorPlacements(e).size() == 1);
    CHECK(decorPlacements(e)[0].width == Approx(0.1));
}

TEST_CASE("an edge's tiles follow its bend by arc length", "[decor]") {
    DrawItem e = item(ElemClass::Edge, 0, {{"decor_href", std::string("tie.png")}, {"decor_every", 0.5}});
    e.a = {0, 0};
    e.bend = {{1, 0}};
    e.b = {1, 1};
    const std::vector<Placement> p = decorPlacements(e);
    REQUIRE(p.size() == 4);
    const vec2 want[] = {{0.25, 0}, {0.75, 0}, {1, 0.25}, {1, 0.75}};
    const double turn[] = {0, 0, 90, 90};
    for (std::size_t k = 0; k < 4; ++k) {
        CHECK(p[k].centre.x == Approx(want[k].x).margin(1e-12));
        CHECK(p[k].centre.y == Approx(want[k].y).margin(1e-12));
        CHECK(p[k].degrees == Approx(turn[k]));
    }
}

TEST_CASE("a face's grid decoration lies on the spacing's grid from the origin, inside the face and outside its holes", "[decor]") {
    DrawItem f = square(0.5, 2.5, {{"decor_tag", std::string("circle")}, {"decor_every", 1}});
    std::vector<Placement> p = decorPlacements(f);
    REQUIRE(p.size() == 4);
    CHECK(p[0].centre == vec2(1, 1));
    CHECK(p[3].centre == vec2(2, 2));
    f.holes = {{{0.8, 0.8}, {0.8, 1.2}, {1.2, 1.2}, {1.2, 0.8}}};
    p = decorPlacements(f);
    REQUIRE(p.size() == 3);
    for (const Placement& q : p) CHECK(q.centre != vec2(1, 1));
}

TEST_CASE("a face's scattered decoration: density x area placements, inside, apart, the same for the same face", "[decor]") {
    DrawItem f = square(0, 10, {{"decor_tag", std::string("circle")}, {"decor_density", 0.5}});
    f.holes = {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}};   // area 100 - 4
    const std::vector<Placement> p = decorPlacements(f);
    REQUIRE(p.size() == 48);
    const double least = 0.7 / std::sqrt(0.5);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const vec2 c = p[i].centre;
        CHECK((c.x > 0 && c.x < 10 && c.y > 0 && c.y < 10));
        CHECK_FALSE((c.x > 4 && c.x < 6 && c.y > 4 && c.y < 6));
        for (std::size_t j = 0; j < i; ++j) CHECK(length(p[j].centre - c) >= least);
    }
    CHECK(decorPlacements(f)[7].centre == p[7].centre);
    f.id = 1;
    CHECK(decorPlacements(f)[7].centre != p[7].centre);
}

TEST_CASE("decorations in SVG: after their element, decor_PROP as PROP, drawn on an element whose tag is none", "[decor][svg]") {
    DrawItem n = item(ElemClass::Node, 0, {{"tag", std::string("none")}, {"decor_href", std::string("tree.png")}, {"decor_width", 2},
                                           {"decor_height", 1}, {"decor_opacity", 0.5}});
    n.a = {3, 4};
    DrawItem e = item(ElemClass::Edge, 0, {{"stroke", std::string("red")}, {"decor_tag", std::string("circle")}, {"decor_every", 0.5},
                                           {"decor_r", 0.05}, {"decor_fill", std::string("blue")}});
    e.a = {0, 0};
    e.b = {1, 0};
    const std::string svg = writeSvg({n, e}, {});
    INFO(svg);
    CHECK(contains(svg, "<image href=\"tree.png\" x=\"-1\" y=\"-0.5\" width=\"2\" height=\"1\" transform=\"translate(3 4) rotate(0) "
                        "scale(1 -1)\" opacity=\"0.5\"/>"));
    CHECK_FALSE(contains(svg, "<circle cx=\"3\""));   // the node itself is not drawn
    CHECK(contains(svg, "<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"0\" stroke-width=\"0.05\" stroke=\"red\"/>\n"
                        "<circle cx=\"0.25\" cy=\"0\" r=\"0.05\" fill=\"blue\"/>\n<circle cx=\"0.75\" cy=\"0\" r=\"0.05\" fill=\"blue\"/>"));
    CHECK(count(svg, "decor") == 0);   // no decor_ property leaks into an element
    // The frame holds the image (x up to 4, y up to 4.5): the viewBox is
    // "x0 -top w h" with the margin's 2 % of the size and the stroke.
    const std::string tail = svg.substr(svg.find("viewBox=\"") + 9);
    double x0 = 0, top = 0, w = 0, h = 0;
    REQUIRE(std::sscanf(tail.c_str(), "%lf %lf %lf %lf", &x0, &top, &w, &h) == 4);
    CHECK(x0 + w > 4);
    CHECK(-top > 4.5);
}
