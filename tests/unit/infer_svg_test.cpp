// g2d infer's SVG reader: elements, transforms, colours, the plane graph
// (merging, T-junctions, crossings, duplicates), area sides and the errors.
#include <catch2/catch.hpp>

#include <cmath>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "infer/example_svg.hpp"
#include "infer/svg_syntax.hpp"

using namespace g2d::infer;

namespace {

// The body starts on line 2.
std::string svgDoc(const std::string& body) {
    return "<svg xmlns=\"http://www.w3.org/2000/svg\">\n" + body + "\n</svg>\n";
}

ExampleShape read(const std::string& body) { return readExampleSvg(svgDoc(body), "dir/t.svg"); }

std::string errorOf(const std::string& text) {
    try {
        readExampleSvg(text, "t.svg");
    } catch (const InputError& e) {
        return e.message;
    }
    return "no error";
}
std::string bodyError(const std::string& body) { return errorOf(svgDoc(body)); }

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// "(x,y) ..." in example units.
std::string vertices(const ExampleShape& s) {
    std::string out;
    for (const Point& p : s.vertices) out += (out.empty() ? "(" : " (") + num(p.x) + "," + num(p.y) + ")";
    return out;
}

// "from>to brush left|right" per edge.
std::string edges(const ExampleShape& s) {
    std::string out;
    for (const ExampleEdge& e : s.edges)
        out += (out.empty() ? "" : " ") + std::to_string(e.from) + ">" + std::to_string(e.to) + " b" +
               std::to_string(e.brush) + " " + std::to_string(e.leftArea) + "|" + std::to_string(e.rightArea);
    return out;
}

std::string labels(const ExampleShape& s) {
    std::string out;
    for (const EdgeBrush& b : s.brushes) out += b.name + "=" + b.color + " ";
    for (const AreaLabel& a : s.areas) out += a.name + "=" + a.color + " ";
    return out;
}

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST_CASE("svg: a filled triangle has its inside on the right when clockwise, on the left when not", "[infer][svg]") {
    // On screen (y down) 0,0 -> 40,0 -> 0,40 turns clockwise; flipped to y up it still does.
    const ExampleShape cw = read(R"svg(<polygon points="0,0 40,0 0,40" fill="red" stroke="blue"/>)svg");
    CHECK(cw.name == "t");
    CHECK(vertices(cw) == "(0,0) (1,0) (0,-1)");
    CHECK(edges(cw) == "0>1 b0 -1|0 1>2 b0 -1|0 2>0 b0 -1|0");
    CHECK(labels(cw) == "Line0=#0000ff Area0=#ff0000 ");
    REQUIRE(cw.brushes.size() == 1);
    REQUIRE(cw.edges.size() == 3);
    CHECK(cw.brushes[0].minLength == 0);
    CHECK(cw.brushes[0].maxLength == 0);
    CHECK_FALSE(cw.brushes[0].rigid);
    CHECK(cw.edges[2].where == "line 2");
    CHECK(cw.vertexWhere == std::vector<std::string>{"line 2", "line 2", "line 2"});
    CHECK(cw.canvasWidth == 0);

    const ExampleShape ccw = read(R"svg(<polygon points="0,0 0,40 40,0" fill="red" stroke="blue"/>)svg");
    CHECK(edges(ccw) == "0>1 b0 0|-1 1>2 b0 0|-1 2>0 b0 0|-1");
}

TEST_CASE("svg: two rectangles sharing a side give it both areas", "[infer][svg]") {
    const ExampleShape s = read(R"svg(<g stroke="black">
<rect x="0" y="0" width="40" height="40" fill="red"/>
<rect x="40" y="0" width="40" height="40" fill="#00f"/>
</g>)svg");
    CHECK(vertices(s) == "(0,0) (1,0) (1,-1) (0,-1) (2,0) (2,-1)");
    // The shared side 1>2 is drawn by both; the second drawing is the same edge.
    CHECK(edges(s) == "0>1 b0 -1|0 1>2 b0 1|0 2>3 b0 -1|0 3>0 b0 -1|0 1>4 b0 -1|1 4>5 b0 -1|1 5>2 b0 -1|1");
    CHECK(labels(s) == "Line0=#000000 Area0=#ff0000 Area1=#0000ff ");
}

TEST_CASE("svg: path data with relative, implicit and H/V/Z commands", "[infer][svg]") {
    const ExampleShape s = read(R"svg(<path stroke="black" fill="none" d="m 40,40 h 40 v 40 H 40 z m 80-40 l 40 0 0 40 Z M200 0 L 240 0 240 40"/>)svg");
    CHECK(vertices(s) == "(1,-1) (2,-1) (2,-2) (1,-2) (3,0) (4,0) (4,-1) (5,0) (6,0) (6,-1)");
    CHECK(edges(s) == "0>1 b0 -1|-1 1>2 b0 -1|-1 2>3 b0 -1|-1 3>0 b0 -1|-1 4>5 b0 -1|-1 5>6 b0 -1|-1 6>4 b0 -1|-1 "
                      "7>8 b0 -1|-1 8>9 b0 -1|-1");
    // After Z a drawing command starts a new subpath where the last one started.
    const ExampleShape t = read(R"svg(<path stroke="black" fill="none" d="M 0 0 H 40 V 40 Z L 0 40"/>)svg");
    CHECK(edges(t) == "0>1 b0 -1|-1 1>2 b0 -1|-1 2>0 b0 -1|-1 0>3 b0 -1|-1");
    // A closed subpath is an area; an open one, even filled, is not.
    const ExampleShape u = read(R"svg(<path stroke="black" fill="red" d="M 0 0 H 40 V 40 Z M 80 0 H 120 V 40"/>)svg");
    CHECK(edges(u) == "0>1 b0 -1|0 1>2 b0 -1|0 2>0 b0 -1|0 3>4 b0 -1|-1 4>5 b0 -1|-1");
    // Numbers may run together as SVG allows.
    const ExampleShape v = read(R"svg(<path stroke="black" d="M.5.5L40.5-39.5"/>)svg");
    CHECK(vertices(v) == "(0.0125,-0.0125) (1.0125,0.9875)");
}

TEST_CASE("svg: transforms compose from the root down and give exact coordinates", "[infer][svg]") {
    const ExampleShape s = readExampleSvg(R"svg(<svg xmlns="http://www.w3.org/2000/svg" transform="translate(0,-40)">
<g transform="translate(80,40) scale(2)">
  <line x1="0" y1="0" x2="20" y2="0" transform="rotate(90)" stroke="black"/>
  <line x1="0" y1="0" x2="20" y2="0" transform="rotate(180, 20, 20)" stroke="black"/>
  <line x1="0" y1="0" x2="20" y2="20" transform="matrix(1 0 0 -1 100 0)" stroke="black"/>
  <line x1="0" y1="20" x2="20" y2="20" transform="skewX(45)" stroke="black"/>
  <line x1="20" y1="0" x2="20" y2="20" transform="skewY(-45)" stroke="black"/>
</g>
<g transform="rotate(270)"><line x1="0" y1="0" x2="20" y2="0" stroke="black"/></g>
</svg>)svg",
                                              "t.svg");
    // Root and group together map (x,y) to (80+2x, 2y) user units; rotate(90) takes (20,0) to (0,20);
    // rotate(180,20,20): (0,0)->(40,40), (20,0)->(20,40); matrix: (x,y)->(x+100,-y);
    // skewX(45): (x,y)->(x+y,y); skewY(-45): (x,y)->(x,y-x). Last, rotate(270)
    // alone: (20,0) -> (0,-20), where an inexact cos(270) would leave x off 0.
    const std::vector<Point> want{{2, 0},    {2, -1},   {4, -2},   {3, -2},   {7, 0},
                                  {8, 1},    {3, -1},   {4, -1},   {3, 1},    {3, 0},
                                  {0, 1},    {0, 1.5}};
    REQUIRE(s.vertices.size() == want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        INFO("vertex " << i);
        CHECK(s.vertices[i].x == want[i].x);
        CHECK(s.vertices[i].y == want[i].y);
    }
    CHECK(s.edges.size() == 6);
}

TEST_CASE("svg: colours from attributes, style and ancestors, normalised", "[infer][svg]") {
    const ExampleShape s = read(R"svg(<g stroke="red" style="fill:none">
<line x1="0" y1="0" x2="40" y2="0"/>
<line x1="0" y1="40" x2="40" y2="40" stroke="blue" style="stroke:#0F0"/>
<line x1="0" y1="80" x2="40" y2="80" style="stroke: rgb(0, 0, 255) !important"/>
<line x1="0" y1="120" x2="40" y2="120" stroke="Grey"/>
<line x1="0" y1="160" x2="40" y2="160" stroke="#ABC"/>
<line x1="0" y1="200" x2="40" y2="200" stroke="inherit"/>
<line x1="0" y1="240" x2="40" y2="240" stroke="none"/>
<line x1="0" y1="280" x2="40" y2="280" stroke="rgb(100%, 50%, 0%)"/>
<line x1="0" y1="320" x2="40" y2="320" stroke="transparent"/>
<g style="stroke:LightGoldenRodYellow"><line x1="0" y1="360" x2="40" y2="360"/></g>
</g>
<line x1="0" y1="400" x2="40" y2="400"/>)svg");
    CHECK(labels(s) == "Line0=#ff0000 Line1=#00ff00 Line2=#0000ff Line3=#808080 Line4=#aabbcc Line5=#ff8000 Line6=#fafad2 ");
    CHECK(edges(s) == "0>1 b0 -1|-1 2>3 b1 -1|-1 4>5 b2 -1|-1 6>7 b3 -1|-1 8>9 b4 -1|-1 10>11 b0 -1|-1 "
                      "12>13 b5 -1|-1 14>15 b6 -1|-1");
    // fill defaults to black as in SVG; a filled shape without stroke is an area only.
    const ExampleShape f = read(R"svg(<rect x="0" y="0" width="40" height="40"/>
<polyline points="0,0 40,0 40,40 0,40 0,0" stroke="red" fill="none"/>)svg");
    CHECK(labels(f) == "Line0=#ff0000 Area0=#000000 ");
    CHECK(edges(f) == "0>1 b0 -1|0 1>2 b0 -1|0 2>3 b0 -1|0 3>0 b0 -1|0");
    // Labels nothing uses are left out; the rest keep their order of appearance.
    const ExampleShape g = read(R"svg(<rect x="400" y="0" width="40" height="40" fill="yellow"/>
<rect x="0" y="0" width="40" height="40" fill="orange" stroke="purple"/>)svg");
    CHECK(labels(g) == "Line0=#800080 Area0=#ffa500 ");
}

TEST_CASE("svg: the innermost filled shape labels a side, and holes by fill-rule do not count", "[infer][svg]") {
    // A small square drawn on a big one (either order): its inside is its own.
    const ExampleShape s = read(R"svg(<rect x="40" y="40" width="40" height="40" fill="red" stroke="black"/>
<rect x="0" y="0" width="120" height="120" fill="blue"/>)svg");
    CHECK(edges(s) == "0>1 b0 1|0 1>2 b0 1|0 2>3 b0 1|0 3>0 b0 1|0");
    CHECK(labels(s) == "Line0=#000000 Area0=#ff0000 Area1=#0000ff ");
    // A ring with a hole: the inner outline has the ring on one side, nothing on the other.
    const ExampleShape h = read(R"svg(<path fill="green" fill-rule="evenodd" d="M0 0 H120 V120 H0 Z M40 40 H80 V80 H40 Z"/>
<path stroke="black" fill="none" d="M40 40 H80 V80 H40 Z"/>)svg");
    CHECK(edges(h) == "0>1 b0 0|-1 1>2 b0 0|-1 2>3 b0 0|-1 3>0 b0 0|-1");
    const ExampleShape n = read(R"svg(<path fill="green" d="M0 0 H120 V120 H0 Z M40 40 H80 V80 H40 Z"/>
<path stroke="black" fill="none" d="M40 40 H80 V80 H40 Z"/>)svg");
    CHECK(edges(n) == "0>1 b0 0|0 1>2 b0 0|0 2>3 b0 0|0 3>0 b0 0|0");   // nonzero, same turn: filled

    // A fill without stroke under lines drawn on its outline, one side bent
    // 0.3 units inwards by a T-junction: the fill follows the bend.
    const ExampleShape b = read(R"svg(<rect x="0" y="0" width="80" height="40" fill="red"/>
<polyline points="0,40 0,0 80,0 80,40 0,40" stroke="black" fill="none"/>
<line x1="40" y1="0.3" x2="40" y2="40" stroke="black"/>)svg");
    CHECK(vertices(b) == "(0,-1) (0,0) (2,0) (2,-1) (1,-0.0075) (1,-1)");
    CHECK(edges(b) == "0>1 b0 -1|0 1>4 b0 -1|0 4>2 b0 -1|0 2>3 b0 -1|0 3>5 b0 -1|0 5>0 b0 -1|0 4>5 b0 0|0");
    // A fill whose corners are off the drawn corners by less than the tolerance.
    const ExampleShape c = read(R"svg(<rect x="0.3" y="0.2" width="80" height="40" fill="red"/>
<polygon points="0,0 80,0 80,40 0,40" stroke="black" fill="none"/>)svg");
    CHECK(edges(c) == "0>1 b0 -1|0 1>2 b0 -1|0 2>3 b0 -1|0 3>0 b0 -1|0");
    // Of two equal shapes the later, painted on top, labels the side.
    const ExampleShape t = read(R"svg(<rect width="40" height="40" fill="red" stroke="black"/>
<rect width="40" height="40" fill="blue"/>)svg");
    CHECK(labels(t) == "Line0=#000000 Area0=#0000ff ");
    CHECK(edges(t) == "0>1 b0 -1|0 1>2 b0 -1|0 2>3 b0 -1|0 3>0 b0 -1|0");
}

TEST_CASE("svg: close ends merge, T-junctions and crossings split, duplicates and zero lengths go", "[infer][svg]") {
    // The second line starts 0.36 units from the first one's end: one vertex, the first's.
    const ExampleShape m = read(R"svg(<g stroke="black"><line x1="0" y1="0" x2="40" y2="0"/><line x1="40.3" y1="0.2" x2="80" y2="0"/></g>)svg");
    CHECK(vertices(m) == "(0,0) (1,0) (2,0)");
    CHECK(edges(m) == "0>1 b0 -1|-1 1>2 b0 -1|-1");

    // A T-junction 0.3 units off the line it meets splits that line there.
    const ExampleShape t = read(R"svg(<g stroke="black"><line x1="0" y1="0" x2="80" y2="0"/><line x1="40" y1="0.3" x2="40" y2="40"/></g>)svg");
    CHECK(vertices(t) == "(0,0) (2,0) (1,-0.0075) (1,-1)");
    CHECK(edges(t) == "0>2 b0 -1|-1 2>1 b0 -1|-1 2>3 b0 -1|-1");

    // A grid drawn as four long lines: four crossings, each line in three.
    const ExampleShape g = read(R"svg(<g stroke="black">
<line x1="0" y1="40" x2="120" y2="40"/><line x1="0" y1="80" x2="120" y2="80"/>
<line x1="40" y1="0" x2="40" y2="120"/><line x1="80" y1="0" x2="80" y2="120"/>
</g>)svg");
    CHECK(vertices(g) == "(0,-1) (3,-1) (0,-2) (3,-2) (1,0) (1,-3) (2,0) (2,-3) (1,-1) (2,-1) (1,-2) (2,-2)");
    CHECK(edges(g) == "0>8 b0 -1|-1 8>9 b0 -1|-1 9>1 b0 -1|-1 2>10 b0 -1|-1 10>11 b0 -1|-1 11>3 b0 -1|-1 "
                      "4>8 b0 -1|-1 8>10 b0 -1|-1 10>5 b0 -1|-1 6>9 b0 -1|-1 9>11 b0 -1|-1 11>7 b0 -1|-1");
    REQUIRE(g.vertexWhere.size() == 12);
    CHECK(g.vertexWhere[8] == "line 3");

    // Drawn twice alike: one edge; overlapping collinear lines share the overlap.
    const ExampleShape d = read(R"svg(<g stroke="black"><line x1="0" y1="0" x2="80" y2="0"/><line x1="40" y1="0" x2="120" y2="0"/>
<line x1="120" y1="0" x2="40" y2="0"/></g>)svg");
    CHECK(vertices(d) == "(0,0) (2,0) (1,0) (3,0)");
    CHECK(edges(d) == "0>2 b0 -1|-1 2>1 b0 -1|-1 1>3 b0 -1|-1");

    // A step shorter than the tolerance is no edge.
    const ExampleShape z = read(R"svg(<polyline stroke="black" fill="none" points="0,0 40,0 40,0.2 80,0"/>)svg");
    CHECK(edges(z) == "0>1 b0 -1|-1 1>2 b0 -1|-1");
}

TEST_CASE("svg: skipped parts, hidden layers, other namespaces and the title", "[infer][svg]") {
    const ExampleShape s = readExampleSvg(R"svg(<?xml version="1.0"?>
<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd">
<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
     viewBox="0 0 10 10" width="100mm">
  <title> A Test </title>
  <desc>ignored</desc>
  <metadata><foo/></metadata>
  <inkscape:namedview><inkscape:grid/></inkscape:namedview>
  <defs><circle r="5"/><line x1="0" x2="99" stroke="red"/></defs>
  <style/>
  <g inkscape:label="hidden" style="display:none"><text>x</text><line x2="99" stroke="red"/></g>
  <g display="none"><line x2="99" stroke="red"/></g>
  <line x1="0" y1="0" x2="40" y2="0" stroke="black" inkscape:label="kept"/>
</svg>)svg",
                                            "x/y/z.svg");
    CHECK(s.name == "A Test");
    CHECK(vertices(s) == "(0,0) (1,0)");
    CHECK(edges(s) == "0>1 b0 -1|-1");
    REQUIRE(s.edges.size() == 1);
    CHECK(s.edges[0].where == "line 13");
}

TEST_CASE("svg: the house example", "[infer][svg]") {
    const std::string path = G2D_SOURCE_DIR "/examples/infer/house.svg";
    const ExampleShape s = readExampleSvg(readFile(path), path);
    CHECK(s.name == "House");
    CHECK(vertices(s) == "(0,-2) (2,-2) (2,-4) (0,-4) (1,-1) (0.75,-4) (0.75,-3) (1.25,-3) (1.25,-4)");
    // Body (Area0) below the roof (Area1); the door's line stands inside the body,
    // its feet splitting the bottom side.
    CHECK(edges(s) == "0>1 b0 1|0 1>2 b0 -1|0 2>8 b0 -1|0 8>5 b0 -1|0 5>3 b0 -1|0 3>0 b0 -1|0 "
                      "1>4 b0 1|-1 4>0 b0 1|-1 5>6 b1 0|0 6>7 b1 0|0 7>8 b1 0|0");
    CHECK(labels(s) == "Line0=#000000 Line1=#8b4513 Area0=#d2b48c Area1=#b22222 ");
    REQUIRE(s.edges.size() == 11);
    CHECK(s.edges[8].where == "line 9");
}

TEST_CASE("svg: a turn by any angle is a turn (an angle past 10^306 degrees is reduced first)", "[infer][svg]") {
    const svg::Matrix m = svg::parseTransform("rotate(1e308)");
    const double turned = std::fmod(1e308, 360.0) * M_PI / 180;
    CHECK(m.a == std::cos(turned));
    CHECK(m.b == std::sin(turned));
    CHECK(svg::parseTransform("rotate(-450)").b == -1);
}

TEST_CASE("svg: errors say where", "[infer][svg]") {
    CHECK(errorOf("<svg>\n<g>\n</svg>") == "t.svg:3: not well-formed XML: Opening and ending tag mismatch: g line 2 and svg");
    CHECK(errorOf("") == "t.svg:1: not well-formed XML: Document is empty");
    CHECK(errorOf("<html>\n</html>") == "t.svg:1: the root element is <html>, not <svg>");
    CHECK(errorOf(R"svg(<svg xmlns="http://www.w3.org/2000/svg"><rect width="40" height="40" fill="red"/></svg>)svg") ==
          "t.svg:1: the drawing has no edges: only shapes with a stroke draw them");

    CHECK(bodyError("<g>\n<svg/></g>") == "t.svg:3: a nested <svg> is not supported");
    CHECK(bodyError("<use href=\"#a\"/>") ==
          "t.svg:2: <use> is not supported: turn clones into plain shapes (Inkscape: Edit > Clone > Unlink Clone)");
    CHECK(bodyError("<text>hi</text>") == "t.svg:2: <text> is not supported: an example holds only lines and filled areas");
    CHECK(bodyError("<image href=\"a.png\"/>") == "t.svg:2: <image> is not supported: an example holds only lines and filled areas");
    CHECK(bodyError("<circle r=\"4\"/>") == "t.svg:2: <circle> is not supported: edges must be straight (draw a polygon)");
    CHECK(bodyError("<ellipse rx=\"4\" ry=\"2\"/>") == "t.svg:2: <ellipse> is not supported: edges must be straight (draw a polygon)");
    CHECK(bodyError("<foreignObject/>") == "t.svg:2: <foreignObject> is not supported");
    CHECK(bodyError("<style>line { stroke: red }</style>") ==
          "t.svg:2: <style> sheets are not supported: give colours as attributes or in style=\"...\"");

    for (const char c : std::string("CcSsQqTtAa")) {
        INFO(c);
        CHECK(bodyError(std::string("<path stroke=\"red\" d=\"M 0 0 ") + c + " 1 1 2 2 3 3 4\"/>") ==
              std::string("t.svg:2: <path>: d: the command '") + c +
                  "' draws a curve: only straight segments (M, L, H, V, Z) are supported");
    }
    CHECK(bodyError("<path d=\"L 0 0\"/>") == "t.svg:2: <path>: d: path data must start with M or m");
    CHECK(bodyError("<path d=\"M 0 0 L 10\"/>") == "t.svg:2: <path>: d: expected a number at the end");
    CHECK(bodyError("<path d=\"M 0 0 L 10 x\"/>") == "t.svg:2: <path>: d: expected a number at \"x\"");
    CHECK(bodyError("<path d=\"M 0 0 L 10 10 x\"/>") == "t.svg:2: <path>: d: 'x' is not a path command");
    CHECK(bodyError("<path d=\"M 0 0 Z 4\"/>") == "t.svg:2: <path>: d: expected a command at \"4\"");
    CHECK(bodyError("<path d=\"M 0 0 L 1,,2\"/>") == "t.svg:2: <path>: d: expected a number at \",2\"");

    CHECK(bodyError("\n<line x1=\"abc\"/>") == "t.svg:3: <line>: x1 \"abc\" is not a number");
    CHECK(bodyError("<line x1=\"10mm\"/>") == "t.svg:2: <line>: x1 \"10mm\" is not a number");
    CHECK(bodyError("<line y2=\"1e999\"/>") == "t.svg:2: <line>: y2 \"1e999\" is not a number");
    CHECK(bodyError("<line x2=\"1e300\" transform=\"scale(1e300)\"/>") ==
          "t.svg:2: <line>: a point is out of range after the transforms");
    CHECK(bodyError("<rect width=\"4\" height=\"4\" rx=\"1\"/>") == "t.svg:2: <rect>: rounded corners (rx, ry) are not supported");
    CHECK(bodyError("<rect width=\"-4\" height=\"4\"/>") == "t.svg:2: <rect>: a negative width or height is not allowed");
    CHECK(bodyError("<polygon points=\"0,0 1,1 2\"/>") == "t.svg:2: <polygon>: points has an odd number of coordinates");
    CHECK(bodyError("<polyline points=\"0,0 a\"/>") == "t.svg:2: <polyline>: points: expected a number at \"a\"");

    CHECK(bodyError("<g transform=\"translate(1,2,3)\"/>") ==
          "t.svg:2: <g>: transform \"translate(1,2,3)\": translate takes 1 or 2 numbers, not 3");
    CHECK(bodyError("<g transform=\"turn(1)\"/>") == "t.svg:2: <g>: transform \"turn(1)\": \"turn\" is not a transform");
    CHECK(bodyError("<g transform=\"rotate(1 2)\"/>") == "t.svg:2: <g>: transform \"rotate(1 2)\": rotate takes 1 or 3 numbers, not 2");
    CHECK(bodyError("<g transform=\"scale(2\"/>") == "t.svg:2: <g>: transform \"scale(2\": missing \")\" after scale");
    CHECK(bodyError("<g transform=\"skewX(90)\"/>") == "t.svg:2: <g>: transform \"skewX(90)\": skewX(90) has no finite matrix");
    CHECK(bodyError("<g transform=\"scale(1e200) scale(1e200)\"/>") ==
          "t.svg:2: <g>: transform \"scale(1e200) scale(1e200)\": the transform overflows at scale");
    CHECK(bodyError("<path d=\"m 1e308 0 l 1e308 0\"/>") ==
          "t.svg:2: <path>: d: the relative coordinates add up past any number before the end");

    CHECK(bodyError("<line stroke=\"bogus\"/>") == "t.svg:2: <line>: stroke \"bogus\" is not a colour");
    CHECK(bodyError("<line style=\"fill: #12\"/>") == "t.svg:2: <line>: fill \"#12\" is not a colour");
    CHECK(bodyError("<rect fill=\"url(#g)\"/>") ==
          "t.svg:2: <rect>: fill \"url(#g)\": gradients and patterns are not supported, only plain colours");
    CHECK(bodyError("<g stroke=\"currentColor\"/>") == "t.svg:2: <g>: stroke \"currentColor\" is not supported, only plain colours");
    CHECK(bodyError("<g fill-rule=\"odd\"/>") == "t.svg:2: <g>: fill-rule \"odd\" is not nonzero or evenodd");

    CHECK(bodyError("<line x2=\"40\" stroke=\"red\"/>\n<line x1=\"200\" y1=\"200\" x2=\"200.2\" y2=\"200\" stroke=\"red\"/>") ==
          "t.svg:3: <line>: draws only a point at (200, 200), which touches no edge");
    CHECK(bodyError("<line x2=\"40\" stroke=\"red\"/>\n<path stroke=\"red\" d=\"M 80 80 z\"/>") ==
          "t.svg:3: <path>: draws only a point at (80, 80), which touches no edge");
    CHECK(bodyError("<line x2=\"80\" stroke=\"red\"/>\n<line x1=\"80\" x2=\"40\" stroke=\"blue\"/>") ==
          "t.svg:3: <line>: the edge from (80, 0) to (40, 0) has stroke #0000ff here and #ff0000 at line 2");
}

TEST_CASE("svg: a point on an edge is no isolated point", "[infer][svg]") {
    const ExampleShape s = read(R"svg(<line x1="0" y1="0" x2="80" y2="0" stroke="red"/>
<line x1="40" y1="0" x2="40.1" y2="0" stroke="red"/>)svg");
    CHECK(vertices(s) == "(0,0) (2,0) (1,0)");
    CHECK(edges(s) == "0>2 b0 -1|-1 2>1 b0 -1|-1");
}
