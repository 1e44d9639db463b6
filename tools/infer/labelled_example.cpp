#include "infer/labelled_example.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "infer/direction_groups.hpp"
#include "infer/straighten.hpp"

namespace g2d::infer {
namespace {

constexpr double kPi = 3.14159265358979323846;

double degrees(double radians) { return radians * 180.0 / kPi; }
// Into [-180, 180).
double wrap360(double a) {
    a = std::fmod(a + 180.0, 360.0);
    if (a < 0) a += 360.0;
    return a - 180.0;
}

std::string at(const ExampleShape& s, int v) {
    char buf[64];
    // + 0.0: no "-0".
    std::snprintf(buf, sizeof buf, "(%g, %g)", s.vertices[static_cast<std::size_t>(v)].x + 0.0, s.vertices[static_cast<std::size_t>(v)].y + 0.0);
    return buf;
}

double cross(Point a, Point b, Point c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// Proper crossings, and a vertex touching another edge: a plane drawing has neither.
void checkPlane(const ExampleShape& s) {
    const auto& V = s.vertices;
    for (std::size_t i = 0; i < s.edges.size(); ++i) {
        const ExampleEdge& e = s.edges[i];
        const Point a = V[static_cast<std::size_t>(e.from)], b = V[static_cast<std::size_t>(e.to)];
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        for (std::size_t v = 0; v < V.size(); ++v) {
            if (static_cast<int>(v) == e.from || static_cast<int>(v) == e.to) continue;
            const Point p = V[v];
            const double t = ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / (len * len);
            if (t > 0 && t < 1 && std::fabs(cross(a, b, p)) / len < 1e-9 * std::max(1.0, len))
                throw InputError{s.source + ": " + e.where + ": the edge passes through the vertex at " + at(s, static_cast<int>(v))};
        }
        for (std::size_t j = i + 1; j < s.edges.size(); ++j) {
            const ExampleEdge& f = s.edges[j];
            if (f.from == e.from || f.from == e.to || f.to == e.from || f.to == e.to) continue;
            const Point c = V[static_cast<std::size_t>(f.from)], d = V[static_cast<std::size_t>(f.to)];
            const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
            if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
                throw InputError{s.source + ": " + e.where + ": the edge crosses " + f.where + "; an example must be a plane drawing"};
        }
    }
}

}  // namespace

double LabelledExample::direction(int half) const {
    const double theta = labels[static_cast<std::size_t>(edgeOfHalf(half))].theta;
    return barred(half) ? theta - 180.0 : theta;
}

LabelledExample labelExample(const ExampleShape& shape, const LabelOptions& options) {
    LabelledExample out;
    out.shape = shape;
    const auto& V = shape.vertices;
    std::vector<int> degree(V.size(), 0);
    for (const ExampleEdge& e : shape.edges) {
        ++degree[static_cast<std::size_t>(e.from)];
        ++degree[static_cast<std::size_t>(e.to)];
    }
    for (std::size_t v = 0; v < V.size(); ++v)
        if (degree[v] == 0)
            throw InputError{shape.source + ": " + (v < shape.vertexWhere.size() ? shape.vertexWhere[v] + ": " : std::string()) +
                             "the vertex at " + at(shape, static_cast<int>(v)) + " has no edges"};
    checkPlane(shape);

    std::vector<double> oriented, line;   // per edge: from -> to direction, and as a line
    std::vector<double> length;
    std::vector<DirectedEdge> directed;
    for (const ExampleEdge& e : shape.edges) {
        const Point a = V[static_cast<std::size_t>(e.from)], b = V[static_cast<std::size_t>(e.to)];
        const double d = degrees(std::atan2(b.y - a.y, b.x - a.x));
        oriented.push_back(wrap360(d));
        line.push_back(wrap180(d));
        length.push_back(std::hypot(b.x - a.x, b.y - a.y));
        directed.push_back({e.from, e.to, d, length.back()});
    }
    DirectionOptions directionOptions;
    directionOptions.tolerance = options.angleTolerance;
    const DirectionGroups found = groupDirections(directed, directionOptions);
    const std::vector<int>& groupOf = found.groupOf;
    std::vector<double> groups = found.direction;
    straighten(shape, groupOf, groups);

    // Labels: (brush, left, right, direction[, length of a rigid edge]).
    std::map<std::tuple<int, int, int, int, double>, int> labelOf;
    out.edgeLabel.resize(shape.edges.size());
    out.edgeFlipped.resize(shape.edges.size());
    for (std::size_t i = 0; i < shape.edges.size(); ++i) {
        const ExampleEdge& e = shape.edges[i];
        const double theta = groups[static_cast<std::size_t>(groupOf[i])];
        if (lineDistance(theta, line[i]) > 1e-9) ++out.snappedEdges;
        const bool flipped = std::fabs(wrap360(oriented[i] - theta)) > 90;
        const int left = flipped ? e.rightArea : e.leftArea, right = flipped ? e.leftArea : e.rightArea;
        const EdgeBrush& brush = shape.brushes[static_cast<std::size_t>(e.brush)];
        const double rigidLength = brush.rigid ? std::round(length[i] * 1e6) / 1e6 : 0;
        const auto key = std::make_tuple(e.brush, left, right, groupOf[i], rigidLength);
        auto [it, added] = labelOf.emplace(key, static_cast<int>(out.labels.size()));
        if (added) {
            EdgeLabel label;
            label.brush = e.brush;
            label.left = left;
            label.right = right;
            label.theta = theta;
            out.labels.push_back(label);
        }
        out.labels[static_cast<std::size_t>(it->second)].edges.push_back(static_cast<int>(i));
        out.edgeLabel[i] = it->second;
        out.edgeFlipped[i] = flipped ? 1 : 0;
    }
    // A brush's length range, where the example does not give it: from half
    // its shortest edge to twice its longest (a range is the brush's, as in
    // the author's app; per label, a short label could never equal a long
    // one where a starter needs it: simple stack's rectangle).
    std::vector<double> brushLo(shape.brushes.size(), 1e300), brushHi(shape.brushes.size(), 0);
    for (std::size_t i = 0; i < shape.edges.size(); ++i) {
        const auto b = static_cast<std::size_t>(shape.edges[i].brush);
        brushLo[b] = std::min(brushLo[b], length[i]);
        brushHi[b] = std::max(brushHi[b], length[i]);
    }
    for (EdgeLabel& label : out.labels) {
        const auto b = static_cast<std::size_t>(label.brush);
        const EdgeBrush& brush = shape.brushes[b];
        if (brush.rigid) {
            // Not rounded: rigid edges close loops with each other (1, 1, √2).
            label.minLength = label.maxLength = length[static_cast<std::size_t>(label.edges.front())];
            for (int e : label.edges) label.minLength = label.maxLength = std::min(label.minLength, length[static_cast<std::size_t>(e)]);
        } else if (brush.maxLength > 0) {
            label.minLength = brush.minLength;
            label.maxLength = brush.maxLength;
        } else {
            label.minLength = std::round(brushLo[b] / 2 * 1e6) / 1e6;
            label.maxLength = std::round(brushHi[b] * 2 * 1e6) / 1e6;
        }
        // Tiled lengths: the brush's unit, else the one asked for; the range holds at least one multiple.
        label.unit = brush.rigid ? 0 : brush.unit > 0 ? brush.unit : options.lengthUnit;
        if (label.unit > 0) {
            label.minLength = std::max(label.minLength, label.unit);
            label.maxLength = std::max(label.maxLength, std::ceil(label.minLength / label.unit - 1e-9) * label.unit);
        }
    }

    // Stars: each vertex's half-edges counter-clockwise; equal stars are one primitive.
    std::vector<std::vector<int>> star(V.size());
    for (std::size_t i = 0; i < shape.edges.size(); ++i) {
        const ExampleEdge& e = shape.edges[i];
        const int label = out.edgeLabel[i];
        const bool flipped = out.edgeFlipped[i] != 0;
        star[static_cast<std::size_t>(e.from)].push_back(halfLabel(label, flipped));   // `from` holds a unless flipped
        star[static_cast<std::size_t>(e.to)].push_back(halfLabel(label, !flipped));
    }
    std::map<std::vector<int>, int> primitiveOf;
    out.vertexType.resize(V.size());
    for (std::size_t v = 0; v < V.size(); ++v) {
        auto& halves = star[v];
        std::stable_sort(halves.begin(), halves.end(), [&](int a, int b) { return out.direction(a) < out.direction(b); });
        for (std::size_t k = 0; k < halves.size(); ++k) {
            const int h = halves[k], g = halves[(k + 1) % halves.size()];
            if (halves.size() > 1 && out.direction(h) == out.direction(g))
                throw InputError{shape.source + ": the vertex at " + at(shape, static_cast<int>(v)) + " has two edges in one direction (" +
                                 std::to_string(out.direction(h)) + "°)" +
                                 (out.snappedEdges > 0 ? "; a smaller --angle-tolerance may keep them apart" : "")};
        }
        // The wedge between two consecutive half-edges is one area: left of the first, right of the next.
        for (std::size_t k = 0; k < halves.size(); ++k) {
            const int h = halves[k], g = halves[(k + 1) % halves.size()];
            const EdgeLabel& lh = out.labels[static_cast<std::size_t>(edgeOfHalf(h))];
            const EdgeLabel& lg = out.labels[static_cast<std::size_t>(edgeOfHalf(g))];
            const int leftOfH = barred(h) ? lh.right : lh.left, rightOfG = barred(g) ? lg.left : lg.right;
            if (leftOfH != rightOfG) {
                const auto name = [&](int a) { return a < 0 ? std::string("no area") : shape.areas[static_cast<std::size_t>(a)].name; };
                const std::string between = h == g ? "on the two sides of its only edge (at " +
                                                         std::to_string(std::lround(out.direction(h))) + "°)"
                                                   : "between its edges at " + std::to_string(std::lround(out.direction(h))) +
                                                         "° and " + std::to_string(std::lround(out.direction(g))) + "°";
                throw InputError{shape.source + ": the areas around the vertex at " + at(shape, static_cast<int>(v)) +
                                 " disagree: " + between + " one says " + name(leftOfH) + ", the other " + name(rightOfG)};
            }
        }
        auto [it, added] = primitiveOf.emplace(halves, static_cast<int>(out.primitives.size()));
        if (added) out.primitives.push_back({halves, {}});
        out.primitives[static_cast<std::size_t>(it->second)].vertices.push_back(static_cast<int>(v));
        out.vertexType[v] = it->second;
    }
    return out;
}

}  // namespace g2d::infer
