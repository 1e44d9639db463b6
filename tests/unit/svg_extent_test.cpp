// The frame (viewBox) covers what paths, polylines and texts draw, not only
// the element's position (issue #32: labels and paths were clipped).
#include <catch2/catch.hpp>

#include "g2d/svg_element.hpp"
#include "g2d/svg_extent.hpp"

using namespace g2d::rt;

namespace {

SvgFrame pathFrame(const char* d) {
    SvgFrame f;
    addPathExtent(d, f);
    return f;
}

void checkBox(const SvgFrame& f, double x0, double y0, double x1, double y1) {
    CHECK(f.x0 == Approx(x0).margin(1e-12));
    CHECK(f.y0 == Approx(y0).margin(1e-12));
    CHECK(f.x1 == Approx(x1).margin(1e-12));
    CHECK(f.y1 == Approx(y1).margin(1e-12));
}

}  // namespace

TEST_CASE("path extents: absolute and relative commands, implicit lines, closes", "[svg][extent]") {
    checkBox(pathFrame("M 1 2 L 3 -4"), 1, -4, 3, 2);
    checkBox(pathFrame("M1,2 3,4 5,0"), 1, 0, 5, 4);               // pairs after a move are lines
    checkBox(pathFrame("m 1 1 l 2 0 0 2 z m -5 0 l 1 1"), -4, 1, 3, 3);   // z returns to (1, 1); m is relative to it
    checkBox(pathFrame("M 0 0 H 4 V -2 h -1 v 5"), 0, -2, 4, 3);
    checkBox(pathFrame("M0 0C 1 5 2 -5 3 0"), 0, -5, 3, 5);        // control points cover the curve
    checkBox(pathFrame("M0 0q1 1 2 0t2 0"), 0, 0, 4, 1);
    checkBox(pathFrame("M-1-2L.5.5"), -1, -2, 0.5, 0.5);            // signs and second dots separate numbers
    checkBox(pathFrame("M 1e1 0 L 2E-1 1"), 0.2, 0, 10, 1);
    // An arc: within its radius of both ends.
    checkBox(pathFrame("M 0 0 A 1 1 0 0 1 2 0"), 0, -1, 2, 1);
    checkBox(pathFrame("M 0 0 a 1 1 0 1 0 2 0"), 0, -1, 2, 1);     // flags may run together: "1 0" or "10"
    checkBox(pathFrame("M 0 0 a 1 1 0 10 2 0"), 0, -1, 2, 1);
    // Malformed data stops quietly at the fault (as viewers do).
    checkBox(pathFrame("M 0 0 L 1 1 X 9 9"), 0, 0, 1, 1);
    checkBox(pathFrame("M 0 0 L 1"), 0, 0, 0, 0);
    CHECK(pathFrame("5 5").empty());
    CHECK(pathFrame("").empty());
    SvgFrame points;
    addPointsExtent("0,0 3,1 -2 4", points);
    checkBox(points, -2, 0, 3, 4);
}

TEST_CASE("text extents: the anchor, the font size and the rotation", "[svg][extent]") {
    SvgFrame middle;
    addTextExtent({10, 0}, "abcd", 1, "middle", 0, middle);   // 4 × 0.6 em wide
    checkBox(middle, 8.8, -0.25, 11.2, 0.9);
    SvgFrame start;
    addTextExtent({0, 0}, "ab", 2, "start", 0, start);
    checkBox(start, 0, -0.5, 2.4, 1.8);
    SvgFrame end;
    addTextExtent({0, 0}, "ab", 2, "end", 0, end);
    checkBox(end, -2.4, -0.5, 0, 1.8);
    SvgFrame turned;   // a quarter turn counterclockwise: the text runs up
    addTextExtent({0, 0}, "ab", 2, "start", 90, turned);
    checkBox(turned, -1.8, 0, 0.5, 2.4);
    SvgFrame utf8;     // code points, not bytes
    addTextExtent({0, 0}, "éé", 1, "start", 0, utf8);
    CHECK(utf8.x1 == Approx(1.2));
}

TEST_CASE("a label far out widens the viewBox", "[svg][extent]") {
    DrawItem dot;
    dot.a = {0, 0};
    DrawItem label;
    label.a = {4, 0};
    label.props = {{"tag", Value{std::string("text")}}, {"text", Value{std::string("0123456789")}},
                   {"text_anchor", Value{std::string("start")}}};
    const std::string svg = writeSvg({dot, label}, {});
    // The text runs from x = 4 to 4 + 10 × 0.6 × 0.5 = 7, so the frame ends past 7.
    const auto at = svg.find("viewBox=\"");
    REQUIRE(at != std::string::npos);
    double x = 0, y = 0, w = 0;
    REQUIRE(std::sscanf(svg.c_str() + at, "viewBox=\"%lf %lf %lf", &x, &y, &w) == 3);
    CHECK(x + w > 7);
}
