#include "infer/example_picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>
#include <utility>
#include <vector>

#include "infer/label_colours.hpp"

namespace g2d::infer {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Strong, distinct colours (Tableau 10, then darker ones): dots on light area bands.
const char* const kPrimitivePalette[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948",
                                         "#b07aa1", "#ff9da7", "#9c755f", "#7f7f7f", "#1f5f8b", "#a0522d"};

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return std::string(buf) == "-0.00" ? "0.00" : buf;
}

// Maps example units (y up) into the picture's pixels (y down), with a margin.
struct Frame {
    Point lo{0, 0}, hi{0, 0};
    double scale = 40, margin = 12;
    static Frame around(const std::vector<Point>& points, double scale, double margin) {
        Frame f;
        f.scale = scale;
        f.margin = margin;
        if (points.empty()) return f;
        f.lo = f.hi = points.front();
        for (const Point& p : points) {
            f.lo = {std::min(f.lo.x, p.x), std::min(f.lo.y, p.y)};
            f.hi = {std::max(f.hi.x, p.x), std::max(f.hi.y, p.y)};
        }
        return f;
    }
    double x(double ux) const { return (ux - lo.x) * scale + margin; }
    double y(double uy) const { return (hi.y - uy) * scale + margin; }
    std::string open() const {
        const double w = (hi.x - lo.x) * scale + 2 * margin, h = (hi.y - lo.y) * scale + 2 * margin;
        return "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + num(w) + " " + num(h) + "\" width=\"" + num(w) +
               "\" height=\"" + num(h) + "\">";
    }
    std::string line(Point a, Point b, const std::string& attributes) const {
        return "<line x1=\"" + num(x(a.x)) + "\" y1=\"" + num(y(a.y)) + "\" x2=\"" + num(x(b.x)) + "\" y2=\"" + num(y(b.y)) + "\" " +
               attributes + "/>";
    }
    std::string dot(Point p, double r, const std::string& attributes) const {
        return "<circle cx=\"" + num(x(p.x)) + "\" cy=\"" + num(y(p.y)) + "\" r=\"" + num(r) + "\" " + attributes + "/>";
    }
};

std::string primitiveDot(const Frame& f, Point p, int primitive, double r) {
    return "<circle cx=\"" + num(f.x(p.x)) + "\" cy=\"" + num(f.y(p.y)) + "\" r=\"" + num(r) + "\" fill=\"" + primitiveColour(primitive) +
           "\" stroke=\"#ffffff\" stroke-width=\"1.5\"><title>P" + std::to_string(primitive) + "</title></circle>";
}

// The direction of a label's edges, as a unit vector (y up).
Point unit(double degrees) { return {std::cos(degrees * kPi / 180), std::sin(degrees * kPi / 180)}; }

// Per label: the mean length of its edges in the example (1 if it has none).
std::vector<double> meanLengths(const LabelledExample& ex) {
    std::vector<double> out;
    for (const EdgeLabel& l : ex.labels) {
        double sum = 0;
        for (int e : l.edges) {
            const ExampleEdge& edge = ex.shape.edges[static_cast<std::size_t>(e)];
            const Point a = ex.shape.vertices[static_cast<std::size_t>(edge.from)], b = ex.shape.vertices[static_cast<std::size_t>(edge.to)];
            sum += std::hypot(b.x - a.x, b.y - a.y);
        }
        out.push_back(l.edges.empty() || !(sum > 0) ? 1.0 : sum / static_cast<double>(l.edges.size()));
    }
    return out;
}

// The area left of a half-edge as it leaves its vertex: the label's left for
// the unbarred half (pointing theta), its right for the barred one.
int leftOfHalf(const LabelledExample& ex, int half) {
    const EdgeLabel& l = ex.labels[static_cast<std::size_t>(edgeOfHalf(half))];
    return barred(half) ? l.right : l.left;
}

}  // namespace

std::string primitiveColour(int primitive) {
    return kPrimitivePalette[static_cast<std::size_t>(primitive) % std::size(kPrimitivePalette)];
}

std::string exampleSvg(const LabelledExample& ex) {
    const ExampleShape& s = ex.shape;
    const Frame f = Frame::around(s.vertices, 40, 24);   // room for the names beside the dots
    std::string bands, edges, dots;
    const double offset = 4 / f.scale;   // the bands lie 4 px beside the edge
    for (std::size_t e = 0; e < s.edges.size(); ++e) {
        const ExampleEdge& edge = s.edges[e];
        const Point a = s.vertices[static_cast<std::size_t>(edge.from)], b = s.vertices[static_cast<std::size_t>(edge.to)];
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        if (!(len > 0)) continue;
        const Point left{-(b.y - a.y) / len * offset, (b.x - a.x) / len * offset};
        for (const auto& [area, side] : {std::pair{edge.leftArea, 1.0}, std::pair{edge.rightArea, -1.0}})
            if (area >= 0)
                bands += f.line({a.x + side * left.x, a.y + side * left.y}, {b.x + side * left.x, b.y + side * left.y},
                                "stroke=\"" + areaColour(ex, area) + "\" stroke-width=\"6\" stroke-linecap=\"butt\"");
        edges += f.line(a, b, "stroke=\"" + edgeColour(ex, ex.edgeLabel[e]) + "\" stroke-width=\"2.5\" stroke-linecap=\"round\"");
    }
    for (std::size_t v = 0; v < s.vertices.size(); ++v) {
        dots += primitiveDot(f, s.vertices[v], ex.vertexType[v], 5);
        if (s.vertices.size() <= 60)   // names beside the dots while they do not crowd
            dots += "<text x=\"" + num(f.x(s.vertices[v].x) + 6) + "\" y=\"" + num(f.y(s.vertices[v].y) - 6) +
                    "\" font-size=\"11\" font-family=\"sans-serif\" fill=\"#333333\">P" + std::to_string(ex.vertexType[v]) + "</text>";
    }
    return f.open() + "<g>" + bands + "</g><g>" + edges + "</g><g>" + dots + "</g></svg>";
}

std::string primitiveSvg(const LabelledExample& ex, int primitive) {
    const Primitive& p = ex.primitives[static_cast<std::size_t>(primitive)];
    const Frame f = Frame::around({{-1, -1}, {1, 1}}, 28, 4);
    const Point centre{0, 0};
    std::string wedges, rays;
    const double r = 0.8;
    for (std::size_t i = 0; i < p.halves.size(); ++i) {
        const int h = p.halves[i];
        const double from = ex.direction(h);
        double to = i + 1 < p.halves.size() ? ex.direction(p.halves[i + 1]) : ex.direction(p.halves[0]) + 360;
        if (p.halves.size() == 1) to = from + 360;
        const int area = leftOfHalf(ex, h);
        if (area >= 0) {
            const std::string fill = "fill=\"" + areaColour(ex, area) + "\" fill-opacity=\"0.8\"";
            if (to - from >= 359.999) {
                wedges += f.dot(centre, r * f.scale, fill);
            } else {
                const Point a = unit(from), b = unit(to);
                wedges += "<path d=\"M" + num(f.x(0)) + "," + num(f.y(0)) + " L" + num(f.x(r * a.x)) + "," + num(f.y(r * a.y)) + " A" +
                          num(r * f.scale) + "," + num(r * f.scale) + " 0 " + (to - from > 180 ? "1" : "0") + " 0 " + num(f.x(r * b.x)) +
                          "," + num(f.y(r * b.y)) + " Z\" " + fill + "/>";
            }
        }
        const Point d = unit(from);
        rays += f.line(centre, {d.x, d.y},
                       "stroke=\"" + edgeColour(ex, edgeOfHalf(h)) + "\" stroke-width=\"3\"" + (barred(h) ? " stroke-dasharray=\"5 3\"" : ""));
    }
    return f.open() + wedges + rays + primitiveDot(f, centre, primitive, 5) + "</svg>";
}

std::string ruleSideSvg(const LabelledExample& ex, const RuleSide& side) {
    if (side.primitive.empty() && side.edges.empty()) return "";
    const std::vector<double> lengths = meanLengths(ex);
    // Nodes: vertices k >= 0, interface nodes -1-k. Each edge from -> to points along its label's direction.
    std::map<int, std::vector<std::pair<int, Point>>> next;   // node -> (neighbour, offset to it)
    for (const SideEdge& e : side.edges) {
        const EdgeLabel& l = ex.labels[static_cast<std::size_t>(e.label)];
        const double len = lengths[static_cast<std::size_t>(e.label)] * ((e.from < 0 || e.to < 0) ? 0.5 : 1.0);   // stubs to the interface
        const Point d = unit(l.theta);
        next[e.from].push_back({e.to, {d.x * len, d.y * len}});
        next[e.to].push_back({e.from, {-d.x * len, -d.y * len}});
    }
    std::map<int, Point> at;
    double right = 0;   // pieces side by side: each starts a unit right of the last
    std::vector<int> nodes;   // the vertices, then interface nodes (a side of edge graphs has only these)
    for (int v = 0; v < static_cast<int>(side.primitive.size()); ++v) nodes.push_back(v);
    for (const auto& [n, neighbours] : next)
        if (n < 0) nodes.push_back(n);
    for (int start : nodes) {
        if (at.count(start)) continue;
        const bool first = at.empty();
        std::vector<int> queue{start};
        at[start] = {0, 0};
        for (std::size_t q = 0; q < queue.size(); ++q)
            for (const auto& [n, step] : next[queue[q]])
                if (!at.count(n)) {
                    at[n] = {at[queue[q]].x + step.x, at[queue[q]].y + step.y};
                    queue.push_back(n);
                }
        double least = 0, most = 0;
        for (int n : queue) least = std::min(least, at[n].x), most = std::max(most, at[n].x);
        const double shift = first ? 0 : right + 1 - least;
        for (int n : queue) at[n].x += shift;
        right = first ? most : std::max(right, most + shift);
    }
    std::vector<Point> points;
    for (const auto& [n, p] : at) points.push_back(p);
    const Frame f = Frame::around(points, 24, 8);
    std::string edges, dots;
    for (const SideEdge& e : side.edges)
        edges += f.line(at[e.from], at[e.to],
                        "stroke=\"" + edgeColour(ex, e.label) + "\" stroke-width=\"2.5\"" + ((e.from < 0 || e.to < 0) ? " stroke-dasharray=\"3 2\"" : ""));
    for (const auto& [n, p] : at)
        dots += n >= 0 ? primitiveDot(f, p, side.primitive[static_cast<std::size_t>(n)], 4)
                       : f.dot(p, 2.5, "fill=\"#ffffff\" stroke=\"#555555\" stroke-width=\"1\"");
    return f.open() + edges + dots + "</svg>";
}

}  // namespace g2d::infer
