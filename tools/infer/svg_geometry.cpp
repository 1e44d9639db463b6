// Makes a plane graph of an SVG example's strokes and labels its edges' sides
// from the fills (svg_geometry.hpp).
#include "infer/svg_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>

#include "g2d/plane_geometry.hpp"

namespace g2d::infer::svg {
namespace {

Point minus(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
double cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
double dot(Point a, Point b) { return a.x * b.x + a.y * b.y; }
double dist2(Point a, Point b) { return dot(minus(a, b), minus(a, b)); }

// Where along p -> q the point w projects, and how far it is from the segment.
double along(Point p, Point q, Point w) { return dot(minus(w, p), minus(q, p)) / dist2(p, q); }
double segmentDist2(Point p, Point q, Point w) {
    const double t = std::clamp(along(p, q, w), 0.0, 1.0);
    return dist2({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)}, w);
}

// The vertices, any two at least the tolerance apart; looked up through
// their x order, as a drawing's edges mostly span a small part of it.
class VertexSet {
public:
    explicit VertexSet(double tolerance) : tol_(tolerance) {}

    // The first vertex closer than the tolerance: the first drawn keeps its place.
    int find(Point p) const {
        int best = -1;
        for (auto it = byX_.lower_bound(p.x - tol_); it != byX_.end() && it->first <= p.x + tol_; ++it)
            if (dist2(points_[it->second], p) < tol_ * tol_ && (best < 0 || it->second < best)) best = it->second;
        return best;
    }
    int add(Point p) {
        const int id = static_cast<int>(points_.size());
        points_.push_back(p);
        byX_.emplace(p.x, id);
        return id;
    }
    const Point& operator[](int v) const { return points_[static_cast<std::size_t>(v)]; }
    const std::vector<Point>& points() const { return points_; }

    // The vertices that lie on p -> q (within the tolerance) but are not its
    // ends, in order along it: where a T-junction or a crossing splits it.
    std::vector<int> onSegment(Point p, Point q) const {
        std::vector<std::pair<double, int>> found;
        if (dist2(p, q) == 0) return {};
        const double tol2 = tol_ * tol_;
        for (auto it = byX_.lower_bound(std::min(p.x, q.x) - tol_);
             it != byX_.end() && it->first <= std::max(p.x, q.x) + tol_; ++it) {
            const Point w = points_[it->second];
            if (segmentDist2(p, q, w) < tol2 && dist2(w, p) >= tol2 && dist2(w, q) >= tol2)
                found.push_back({along(p, q, w), it->second});
        }
        std::sort(found.begin(), found.end());
        std::vector<int> out;
        for (const auto& f : found) out.push_back(f.second);
        return out;
    }

private:
    double tol_;
    std::vector<Point> points_;
    std::multimap<double, int> byX_;
};

struct Segment {
    int a, b;
    int element;
};

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v + 0.0);   // + 0.0: no "-0"
    return buf;
}

class Planarizer {
public:
    Planarizer(const PlanarInput& in, ExampleShape& out) : in_(in), out_(out), vertices_(in.tolerance) {}

    void run() {
        collectStrokes();
        addCrossings();
        splitIntoEdges();
        checkIsolated();
        out_.vertices = vertices_.points();
        labelSides();
    }

private:
    [[noreturn]] void fail(int element, const std::string& what) const {
        const DrawnElement& e = in_.elements[static_cast<std::size_t>(element)];
        throw InputError{in_.path + ":" + std::to_string(e.line) + ": <" + e.tag + ">: " + what};
    }
    std::string where(int element) const { return "line " + std::to_string(in_.elements[static_cast<std::size_t>(element)].line); }
    // As the SVG has it: user units, y down.
    std::string drawn(Point p) const { return "(" + number(p.x * in_.svgUnit) + ", " + number(-p.y * in_.svgUnit) + ")"; }

    int vertexAt(Point p, int element) {
        const int found = vertices_.find(p);
        if (found >= 0) return found;
        vertexElement_.push_back(element);
        out_.vertexWhere.push_back(where(element));
        return vertices_.add(p);
    }

    void collectStrokes() {
        for (std::size_t e = 0; e < in_.elements.size(); ++e) {
            if (in_.elements[e].stroke < 0) continue;
            const int element = static_cast<int>(e);
            for (const Outline& o : in_.elements[e].outlines) {
                std::vector<int> ids;
                for (const Point& p : o.points) ids.push_back(vertexAt(p, element));
                for (std::size_t i = 0; i + 1 < ids.size(); ++i) segments_.push_back({ids[i], ids[i + 1], element});
                if (o.closed && ids.size() > 1) segments_.push_back({ids.back(), ids.front(), element});
            }
        }
        std::erase_if(segments_, [](const Segment& s) { return s.a == s.b; });   // shorter than the tolerance
    }

    // Lines drawn across each other (a grid drawn as long lines) meet at a
    // new vertex; crossings near an end are T-junctions, split later.
    void addCrossings() {
        std::vector<std::size_t> order(segments_.size());
        std::iota(order.begin(), order.end(), 0);
        auto minX = [&](std::size_t s) { return std::min(vertices_[segments_[s].a].x, vertices_[segments_[s].b].x); };
        auto maxX = [&](std::size_t s) { return std::max(vertices_[segments_[s].a].x, vertices_[segments_[s].b].x); };
        std::stable_sort(order.begin(), order.end(), [&](std::size_t l, std::size_t r) { return minX(l) < minX(r); });
        const double tol2 = in_.tolerance * in_.tolerance;
        for (std::size_t i = 0; i < order.size(); ++i) {
            const Segment s = segments_[order[i]];
            const Point a = vertices_[s.a], b = vertices_[s.b];
            for (std::size_t j = i + 1; j < order.size() && minX(order[j]) <= maxX(order[i]); ++j) {
                const Segment t = segments_[order[j]];
                if (s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b) continue;
                const Point c = vertices_[t.a], d = vertices_[t.b];
                auto v = [](Point p) { return rt::vec2(p.x, p.y); };
                if (!rt::segmentsCrossProperly(v(a), v(b), v(c), v(d))) continue;
                const double u = cross(minus(c, a), minus(d, c)) / cross(minus(b, a), minus(d, c));
                const Point x{a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)};
                if (dist2(x, a) < tol2 || dist2(x, b) < tol2 || dist2(x, c) < tol2 || dist2(x, d) < tol2) continue;
                vertexAt(x, std::min(s.element, t.element));
            }
        }
    }

    void splitIntoEdges() {
        std::map<std::pair<int, int>, std::size_t> edgeOf;
        for (const Segment& s : segments_) {
            std::vector<int> chain{s.a};
            for (int v : vertices_.onSegment(vertices_[s.a], vertices_[s.b])) chain.push_back(v);
            chain.push_back(s.b);
            const DrawnElement& e = in_.elements[static_cast<std::size_t>(s.element)];
            for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
                const auto key = std::minmax(chain[i], chain[i + 1]);
                if (const auto it = edgeOf.find(key); it != edgeOf.end()) {
                    const ExampleEdge& first = out_.edges[it->second];
                    if (first.brush != e.stroke)
                        fail(s.element, "the edge from " + drawn(vertices_[chain[i]]) + " to " + drawn(vertices_[chain[i + 1]]) +
                                            " has stroke " + in_.strokeColors[static_cast<std::size_t>(e.stroke)] + " here and " +
                                            in_.strokeColors[static_cast<std::size_t>(first.brush)] + " at " + first.where);
                    continue;   // drawn twice alike: one edge
                }
                edgeOf[key] = out_.edges.size();
                out_.edges.push_back({chain[i], chain[i + 1], e.stroke, -1, -1, where(s.element)});
            }
        }
    }

    void checkIsolated() const {
        std::vector<int> degree(vertices_.points().size(), 0);
        for (const ExampleEdge& e : out_.edges) ++degree[static_cast<std::size_t>(e.from)], ++degree[static_cast<std::size_t>(e.to)];
        for (std::size_t v = 0; v < degree.size(); ++v)
            if (degree[v] == 0)
                fail(vertexElement_[v], "draws only a point at " + drawn(vertices_[static_cast<int>(v)]) +
                                            ", which touches no edge");
    }

    struct Ring {
        std::vector<Point> points;
        double area = 0;   // unsigned
        Point low, high;   // bounding box
    };
    struct Filled {
        int fill;
        bool evenOdd;
        std::vector<Ring> rings;
    };

    // A fill's outline moved onto the vertices it passes (within the
    // tolerance), so that an edge drawn along it lies exactly on it.
    Ring ringOf(const Outline& o) const {
        std::vector<Point> snapped;
        for (const Point& p : o.points) {
            const int v = vertices_.find(p);
            snapped.push_back(v >= 0 ? vertices_[v] : p);
        }
        Ring r;
        for (std::size_t i = 0; i < snapped.size(); ++i) {
            const Point p = snapped[i], q = snapped[(i + 1) % snapped.size()];
            if (r.points.empty() || dist2(r.points.back(), p) > 0) r.points.push_back(p);
            for (int v : vertices_.onSegment(p, q)) r.points.push_back(vertices_[v]);
        }
        while (r.points.size() > 1 && dist2(r.points.back(), r.points.front()) == 0) r.points.pop_back();
        double twice = 0;
        r.low = r.high = r.points.empty() ? Point{} : r.points.front();
        for (std::size_t i = 0; i < r.points.size(); ++i) {
            const Point p = r.points[i];
            twice += cross(p, r.points[(i + 1) % r.points.size()]);
            r.low = {std::min(r.low.x, p.x), std::min(r.low.y, p.y)};
            r.high = {std::max(r.high.x, p.x), std::max(r.high.y, p.y)};
        }
        r.area = std::abs(twice) / 2;
        return r;
    }

    static int winding(const Ring& r, Point p) {
        if (p.x < r.low.x || p.x > r.high.x || p.y < r.low.y || p.y > r.high.y) return 0;
        int w = 0;
        for (std::size_t i = 0; i < r.points.size(); ++i) {
            const Point a = r.points[i], b = r.points[(i + 1) % r.points.size()];
            const double side = cross(minus(b, a), minus(p, a));
            if (a.y <= p.y) {
                if (b.y > p.y && side > 0) ++w;
            } else if (b.y <= p.y && side < 0) {
                --w;
            }
        }
        return w;
    }

    // The innermost filled shape at p: the one whose smallest ring around p
    // is smallest; of equal ones, the later, painted on top. A ring that is a
    // hole by the fill rule does not count as around p.
    int areaAt(const std::vector<Filled>& shapes, Point p) const {
        int best = -1;
        double bestSize = std::numeric_limits<double>::infinity();
        for (const Filled& f : shapes) {
            int total = 0;
            double smallest = std::numeric_limits<double>::infinity();
            for (const Ring& r : f.rings)
                if (const int w = winding(r, p); w != 0) total += w, smallest = std::min(smallest, r.area);
            const bool filled = f.evenOdd ? total % 2 != 0 : total != 0;
            if (filled && smallest <= bestSize) best = f.fill, bestSize = smallest;
        }
        return best;
    }

    void labelSides() {
        std::vector<Filled> shapes;
        for (const DrawnElement& e : in_.elements) {
            if (e.fill < 0) continue;
            Filled f{e.fill, e.evenOdd, {}};
            for (const Outline& o : e.outlines)
                if (o.closed && o.points.size() >= 3) f.rings.push_back(ringOf(o));
            if (!f.rings.empty()) shapes.push_back(std::move(f));
        }
        if (shapes.empty()) return;
        // Far less than the tolerance, so the probes stay beside the edge
        // even where it meets another at a sharp angle; far more than rounding.
        const double probe = in_.tolerance / 500;
        for (ExampleEdge& e : out_.edges) {
            const Point a = vertices_[e.from], b = vertices_[e.to];
            const double len = std::sqrt(dist2(a, b));
            const Point mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
            const Point left{-(b.y - a.y) / len * probe, (b.x - a.x) / len * probe};   // counter-clockwise normal
            e.leftArea = areaAt(shapes, {mid.x + left.x, mid.y + left.y});
            e.rightArea = areaAt(shapes, {mid.x - left.x, mid.y - left.y});
        }
    }

    const PlanarInput& in_;
    ExampleShape& out_;
    VertexSet vertices_;
    std::vector<int> vertexElement_;   // per vertex, the element that made it
    std::vector<Segment> segments_;
};

}  // namespace

void planarize(const PlanarInput& in, ExampleShape& out) { Planarizer(in, out).run(); }

}  // namespace g2d::infer::svg
