// Merrell 2023's drawing step (angle_drawing.hpp): the linear system's
// solutions, the sampling of lengths and translations, freeing a fixed
// neighbour after a failed system, and the planarity test.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <tuple>

#include "g2d/angle_drawing.hpp"

using namespace g2d::rt;

namespace {

constexpr double kPi = std::numbers::pi;

struct Builder {
    AngleGraph g;
    int vertex(double x, double y, bool isFree) {
        g.position.push_back({x, y});
        g.free.push_back(isFree ? 1 : 0);
        return static_cast<int>(g.position.size()) - 1;
    }
    int edge(int from, int to, double angle, double lo, double hi, bool created = true) {
        g.edges.push_back({from, to, angle, lo, hi});
        g.created.push_back(created ? 1 : 0);
        return static_cast<int>(g.edges.size()) - 1;
    }
};

DrawingSettings canvas(double lox, double loy, double hix, double hiy) {
    DrawingSettings s;
    s.canvasLo = {lox, loy};
    s.canvasHi = {hix, hiy};
    return s;
}

// The graph with the result's positions.
std::vector<vec2> drawn(const AngleGraph& g, const DrawingResult& r) {
    std::vector<vec2> p = g.position;
    for (std::size_t k = 0; k < r.moved.size(); ++k) p[r.moved[k]] = r.position[k];
    return p;
}

vec2 along(const std::vector<vec2>& p, const AngleEdge& e) { return p[e.to] - p[e.from]; }

// A brand-new rectangle 0-1-2-3 (counter-clockwise from the low left corner).
Builder rectangle(double lo = 1, double hi = 3) {
    Builder b;
    for (int i = 0; i < 4; ++i) b.vertex(0, 0, true);
    b.edge(0, 1, 0, lo, hi);
    b.edge(3, 2, 0, lo, hi);
    b.edge(0, 3, kPi / 2, lo, hi);
    b.edge(1, 2, kPi / 2, lo, hi);
    return b;
}

bool allFinite(const DrawingResult& r) {
    for (const vec2& p : r.position)
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    return true;
}

}  // namespace

TEST_CASE("a new vertex splitting a horizontal edge lies on it", "[angle-drawing]") {
    Builder b;
    const int a = b.vertex(0, 0, false), c = b.vertex(4, 0, false), m = b.vertex(7, 7, true);
    b.edge(a, m, 0, 0.5, 3.5);
    b.edge(m, c, 0, 0.5, 3.5);
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        Rng rng(seed);
        const DrawingResult r = drawAngleGraph(b.g, canvas(-1, -1, 5, 5), rng);
        REQUIRE(r.accepted);
        REQUIRE(r.moved == std::vector<int>{m});
        CHECK(r.systems == 1);
        const vec2 p = r.position[0];
        CHECK(std::abs(p.y) <= 1e-12);
        CHECK(p.x >= 0.5 - 1e-9);
        CHECK(p.x <= 3.5 + 1e-9);
        CHECK(4 - p.x >= 0.5 - 1e-9);
        CHECK(4 - p.x <= 3.5 + 1e-9);
    }
}

TEST_CASE("a brand-new rectangle is drawn inside the canvas at its edges' angles", "[angle-drawing]") {
    const Builder b = rectangle();
    double leftMost = 10, rightMost = 0;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        Rng rng(seed);
        const DrawingResult r = drawAngleGraph(b.g, canvas(0, 0, 10, 10), rng);
        REQUIRE(r.accepted);
        REQUIRE(r.moved == std::vector<int>{0, 1, 2, 3});
        const std::vector<vec2> p = drawn(b.g, r);
        for (const AngleEdge& e : b.g.edges) {
            const vec2 d = along(p, e);
            const double len = std::sqrt(d.x * d.x + d.y * d.y);
            CHECK(std::abs(d.x / len - std::cos(e.angle)) <= 1e-9);
            CHECK(std::abs(d.y / len - std::sin(e.angle)) <= 1e-9);
        }
        for (const vec2& q : p) {
            CHECK(q.x >= -1e-9);
            CHECK(q.x <= 10 + 1e-9);
            CHECK(q.y >= -1e-9);
            CHECK(q.y <= 10 + 1e-9);
        }
        const double width = p[1].x - p[0].x, height = p[3].y - p[0].y;
        CHECK(width >= 1 - 1e-9);
        CHECK(width <= 3 + 1e-9);
        CHECK(height >= 1 - 1e-9);
        CHECK(height <= 3 + 1e-9);
        CHECK(std::abs((p[2].x - p[3].x) - width) <= 1e-9);
        leftMost = std::min(leftMost, p[0].x);
        rightMost = std::max(rightMost, p[0].x);
    }
    // The translation is drawn over the whole canvas, not near the origin.
    CHECK(leftMost < 1);
    CHECK(rightMost > 6);
}

TEST_CASE("samples with a length out of range are rejected", "[angle-drawing]") {
    // Two new edges filling 2.5 between fixed ends, each 0.5 to 1.5 long: the
    // fitted lengths leave the range for some targets.
    Builder b;
    const int a = b.vertex(0, 0, false), c = b.vertex(2.5, 0, false), m = b.vertex(0, 0, true);
    b.edge(a, m, 0, 0.5, 1.5);
    b.edge(m, c, 0, 0.5, 1.5);
    int resampled = 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        Rng rng(seed);
        const DrawingResult r = drawAngleGraph(b.g, canvas(-1, -1, 5, 5), rng);
        REQUIRE(r.accepted);
        CHECK(r.position[0].x >= 1 - 1e-9);
        CHECK(r.position[0].x <= 1.5 + 1e-9);
        resampled += r.samples > 1;
    }
    CHECK(resampled > 0);
}

TEST_CASE("moved vertices stay in the canvas", "[angle-drawing]") {
    // From (9,5) to the right, 0.5 to 3 long, in a canvas ending at x = 10.
    Builder b;
    const int a = b.vertex(9, 5, false), m = b.vertex(0, 0, true);
    b.edge(a, m, 0, 0.5, 3);
    DrawingSettings st = canvas(0, 0, 10, 10);
    st.proposals = 1;   // (a second system would free the fixed end)
    int accepted = 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        Rng rng(seed);
        const DrawingResult r = drawAngleGraph(b.g, st, rng);
        if (!r.accepted) continue;
        ++accepted;
        REQUIRE(r.moved == std::vector<int>{m});
        CHECK(r.position[0].x <= 10 + 1e-9);
    }
    CHECK(accepted > 0);
}

TEST_CASE("new components with cycles: a right triangle and a lattice", "[angle-drawing]") {
    SECTION("triangle") {
        Builder b;
        for (int i = 0; i < 3; ++i) b.vertex(0, 0, true);
        b.edge(0, 1, 0, 1, 3);
        b.edge(1, 2, kPi / 2, 1, 3);
        b.edge(2, 0, 5 * kPi / 4, 1, 5);
        for (std::uint64_t seed = 1; seed <= 20; ++seed) {
            Rng rng(seed);
            const DrawingResult r = drawAngleGraph(b.g, canvas(0, 0, 10, 10), rng);
            REQUIRE(r.accepted);
            const std::vector<vec2> p = drawn(b.g, r);
            const double leg = p[1].x - p[0].x;
            CHECK(std::abs(p[2].y - p[1].y - leg) <= 1e-9);
            CHECK(std::abs(p[2].x - p[1].x) <= 1e-9);
            CHECK(std::abs(p[0].x - p[0].y - (p[2].x - p[2].y)) <= 1e-9);   // the hypotenuse at 45°
        }
    }
    SECTION("5 x 5 lattice of new vertices") {
        constexpr int n = 5;
        Builder b;
        for (int i = 0; i < n * n; ++i) b.vertex(0, 0, true);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                if (x + 1 < n) b.edge(y * n + x, y * n + x + 1, 0, 0.5, 2);
                if (y + 1 < n) b.edge(y * n + x, (y + 1) * n + x, kPi / 2, 0.5, 2);
            }
        Rng rng(4);
        const DrawingResult r = drawAngleGraph(b.g, canvas(0, 0, 10, 10), rng);
        REQUIRE(r.accepted);
        const std::vector<vec2> p = drawn(b.g, r);
        for (const AngleEdge& e : b.g.edges) {
            const vec2 d = along(p, e);
            const double len = std::sqrt(d.x * d.x + d.y * d.y);
            CHECK(std::abs(d.x - len * std::cos(e.angle)) <= 1e-9);
            CHECK(std::abs(d.y - len * std::sin(e.angle)) <= 1e-9);
            CHECK(len >= 0.5 - 1e-9);
            CHECK(len <= 2 + 1e-9);
        }
        CHECK(drawingIsPlanar(p, b.g.edges, 1e-6));
    }
}

TEST_CASE("rigid edges keep their length exactly", "[angle-drawing]") {
    SECTION("from a fixed vertex") {
        Builder b;
        const int a = b.vertex(1, 1, false), m = b.vertex(0, 0, true);
        b.edge(a, m, kPi / 4, 1.5, 1.5);
        Rng rng(3);
        const DrawingResult r = drawAngleGraph(b.g, canvas(0, 0, 10, 10), rng);
        REQUIRE(r.accepted);
        CHECK(std::abs(r.position[0].x - (1 + 1.5 * std::cos(kPi / 4))) <= 1e-12);
        CHECK(std::abs(r.position[0].y - (1 + 1.5 * std::sin(kPi / 4))) <= 1e-12);
        CHECK(r.samples == 1);   // a unique solution is sampled once
    }
    SECTION("in a new rectangle") {
        Builder b = rectangle();
        b.g.edges[0].minLength = b.g.edges[0].maxLength = 2;   // the bottom only: the top follows
        for (std::uint64_t seed = 1; seed <= 20; ++seed) {
            Rng rng(seed);
            const DrawingResult r = drawAngleGraph(b.g, canvas(0, 0, 10, 10), rng);
            REQUIRE(r.accepted);
            const std::vector<vec2> p = drawn(b.g, r);
            CHECK(std::abs(p[1].x - p[0].x - 2) <= 1e-12);
            CHECK(std::abs(p[2].x - p[3].x - 2) <= 1e-12);
        }
    }
}

TEST_CASE("an over-constrained change frees a fixed neighbour", "[angle-drawing]") {
    // A new vertex between (0,0) and (4,1) on a horizontal line: one end must move.
    Builder b;
    const int a = b.vertex(0, 0, false), c = b.vertex(4, 1, false), m = b.vertex(0, 0, true);
    b.edge(a, m, 0, 0.5, 5);
    b.edge(m, c, 0, 0.5, 5);
    Rng rng(11);
    const DrawingResult r = drawAngleGraph(b.g, canvas(-10, -10, 10, 10), rng);
    REQUIRE(r.accepted);
    CHECK(r.systems == 2);
    REQUIRE(r.moved.size() == 2);
    CHECK(r.moved[1] == m);
    CHECK((r.moved[0] == a || r.moved[0] == c));
    const std::vector<vec2> p = drawn(b.g, r);
    CHECK(std::abs(p[a].y - p[m].y) <= 1e-12);
    CHECK(std::abs(p[c].y - p[m].y) <= 1e-12);
    CHECK(p[a].x < p[m].x);
    CHECK(p[m].x < p[c].x);

    SECTION("with one system it is rejected") {
        DrawingSettings one = canvas(-10, -10, 10, 10);
        one.proposals = 1;
        Rng rng1(11);
        const DrawingResult r1 = drawAngleGraph(b.g, one, rng1);
        CHECK_FALSE(r1.accepted);
        CHECK(r1.moved.empty());
        CHECK(r1.position.empty());
        CHECK(r1.systems == 1);
        CHECK(r1.samples == 0);   // an inconsistent system is not sampled
    }
}

TEST_CASE("a created edge between fixed vertices at the wrong angle frees an end", "[angle-drawing]") {
    Builder b;
    const int a = b.vertex(0, 0, false), c = b.vertex(3, 1, false);
    b.edge(a, c, 0, 1, 5);
    std::vector<int> freed;
    for (std::uint64_t seed = 1; seed <= 16; ++seed) {
        Rng rng(seed);
        const DrawingResult r = drawAngleGraph(b.g, canvas(-10, -10, 10, 10), rng);
        REQUIRE(r.accepted);
        REQUIRE(r.moved.size() == 1);
        freed.push_back(r.moved[0]);
        const std::vector<vec2> p = drawn(b.g, r);
        CHECK(std::abs(p[c].y - p[a].y) <= 1e-12);
        CHECK(p[c].x - p[a].x >= 1 - 1e-9);
        CHECK(p[c].x - p[a].x <= 5 + 1e-9);
    }
    // Either end may be the one freed.
    CHECK(std::count(freed.begin(), freed.end(), a) > 0);
    CHECK(std::count(freed.begin(), freed.end(), c) > 0);

    DrawingSettings one = canvas(-10, -10, 10, 10);
    one.proposals = 1;
    Rng rng(1);
    CHECK_FALSE(drawAngleGraph(b.g, one, rng).accepted);
    // At the right angle nothing needs to move.
    b.g.position[c].y = 0;
    Rng rng2(1);
    const DrawingResult ok = drawAngleGraph(b.g, one, rng2);
    CHECK(ok.accepted);
    CHECK(ok.moved.empty());
}

TEST_CASE("a proposal whose every drawing crosses an edge is rejected", "[angle-drawing]") {
    // A new edge from (0,0) to the right, 2 to 3 long; a fixed wall at x = 1.
    Builder b;
    const int a = b.vertex(0, 0, false), m = b.vertex(0, 0, true);
    const int w0 = b.vertex(1, -1, false), w1 = b.vertex(1, 1, false);
    b.edge(a, m, 0, 2, 3);
    b.edge(w0, w1, kPi / 2, 1, 3, false);
    DrawingSettings st = canvas(-10, -10, 10, 10);
    st.proposals = 1;
    Rng rng(5);
    const DrawingResult r = drawAngleGraph(b.g, st, rng);
    CHECK_FALSE(r.accepted);
    CHECK(r.samples == st.samples);
    // The wall beyond reach: accepted.
    b.g.position[w0].x = b.g.position[w1].x = 4;
    Rng rng2(5);
    CHECK(drawAngleGraph(b.g, st, rng2).accepted);
    // Touching the wall's end is not allowed either: the wall at x = 2..3, from y = 0.
    b.g.position[w0] = {2.5, 0};
    b.g.position[w1] = {2.5, 2};
    b.g.edges[0].minLength = b.g.edges[0].maxLength = 2.5;
    Rng rng3(5);
    const DrawingResult r3 = drawAngleGraph(b.g, st, rng3);
    CHECK_FALSE(r3.accepted);
    CHECK(r3.samples == 1);   // one solution: sampled once, not J times
}

TEST_CASE("a created edge between fixed vertices is tested for crossings", "[angle-drawing]") {
    Builder b;
    const int a = b.vertex(0, 0, false), c = b.vertex(2, 0, false);
    const int w0 = b.vertex(1, -1, false), w1 = b.vertex(1, 1, false);
    b.edge(a, c, 0, 1, 3);
    b.edge(w0, w1, kPi / 2, 1, 3, false);
    DrawingSettings st = canvas(-10, -10, 10, 10);
    st.proposals = 1;
    Rng rng(5);
    CHECK_FALSE(drawAngleGraph(b.g, st, rng).accepted);
    b.g.position[w0].x = b.g.position[w1].x = 3;
    Rng rng2(5);
    CHECK(drawAngleGraph(b.g, st, rng2).accepted);
}

TEST_CASE("drawingIsPlanar: crossings, touches, overlaps", "[angle-drawing]") {
    auto planar = [](std::vector<vec2> p, std::vector<std::pair<int, int>> es, double sep = 1e-6,
                     std::vector<char> moved = {}) {
        std::vector<AngleEdge> edges;
        for (auto [f, t] : es) edges.push_back({f, t, 0, 0, 0});
        return drawingIsPlanar(p, edges, sep, moved);
    };
    SECTION("a proper crossing") {
        CHECK_FALSE(planar({{0, 0}, {2, 2}, {0, 2}, {2, 0}}, {{0, 1}, {2, 3}}));
        CHECK_FALSE(planar({{0, 0}, {2, 2}, {0, 2}, {2, 0}}, {{0, 1}, {2, 3}}, 0, {1, 0, 0, 0}));
        // Only pairs with a moved vertex are tested.
        CHECK(planar({{0, 0}, {2, 2}, {0, 2}, {2, 0}, {9, 9}}, {{0, 1}, {2, 3}}, 1e-6, {0, 0, 0, 0, 1}));
        CHECK(planar({{0, 0}, {2, 2}, {0, 3}, {2, 5}}, {{0, 1}, {2, 3}}));
    }
    SECTION("a vertex on an edge's interior (T)") {
        CHECK_FALSE(planar({{0, 0}, {2, 0}, {1, 0}, {1, 1}}, {{0, 1}, {2, 3}}, 0));
        CHECK_FALSE(planar({{0, 0}, {2, 0}, {1, 1e-7}, {1, 1}}, {{0, 1}, {2, 3}}, 1e-6));
        CHECK(planar({{0, 0}, {2, 0}, {1, 1e-5}, {1, 1}}, {{0, 1}, {2, 3}}, 1e-6));
        // Tested from either edge.
        CHECK_FALSE(planar({{0, 0}, {2, 0}, {1, 1e-7}, {1, 1}}, {{0, 1}, {2, 3}}, 1e-6, {0, 0, 0, 1}));
        CHECK_FALSE(planar({{1, 1e-7}, {1, 1}, {0, 0}, {2, 0}}, {{0, 1}, {2, 3}}, 1e-6, {0, 0, 1, 0}));
        // An isolated vertex too.
        CHECK_FALSE(planar({{0, 0}, {2, 0}, {1, 0}}, {{0, 1}}, 0));
        CHECK_FALSE(planar({{0, 0}, {2, 0}, {1, 0}}, {{0, 1}}, 0, {0, 0, 1}));
        CHECK(planar({{0, 0}, {2, 0}, {1, 1}}, {{0, 1}}, 0));
        // Two isolated vertices at one place.
        CHECK_FALSE(planar({{1, 1}, {1, 1}}, {}, 0));
    }
    SECTION("collinear overlap") {
        CHECK_FALSE(planar({{0, 0}, {2, 0}, {1, 0}, {3, 0}}, {{0, 1}, {2, 3}}, 0));
        CHECK_FALSE(planar({{0, 0}, {3, 0}, {1, 0}, {2, 0}}, {{0, 1}, {2, 3}}, 0));
        CHECK(planar({{0, 0}, {1, 0}, {2, 0}, {3, 0}}, {{0, 1}, {2, 3}}, 0));
        // Sharing an end, the same direction from it.
        CHECK_FALSE(planar({{0, 0}, {2, 0}, {1, 0}}, {{0, 1}, {0, 2}}, 0));
        CHECK_FALSE(planar({{0, 0}, {2, 2}, {1, 1}}, {{1, 0}, {0, 2}}, 0));
        // Rounding leaves each far end 1e-16 off the other edge: still one line.
        CHECK_FALSE(planar({{0, 0}, {0.664, 0.747}, {0.664 * 3, 0.747 * 3}}, {{0, 1}, {0, 2}}, 0));
        // Sharing an end, nearly the same direction: the far end within the separation.
        CHECK_FALSE(planar({{0, 0}, {2, 0}, {1, 1e-7}}, {{0, 1}, {0, 2}}, 1e-6));
        CHECK(planar({{0, 0}, {2, 0}, {1, 1e-7}}, {{0, 1}, {0, 2}}, 1e-8));
        // The same two ends twice.
        CHECK_FALSE(planar({{0, 0}, {2, 0}}, {{0, 1}, {1, 0}}, 0));
    }
    SECTION("a shared end is fine") {
        CHECK(planar({{0, 0}, {1, 0}, {0, 1}}, {{0, 1}, {0, 2}}));
        CHECK(planar({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}));
        // Opposite directions from the shared end: a straight path.
        CHECK(planar({{0, 0}, {1, 0}, {-1, 0}}, {{0, 1}, {2, 0}}, 0));
    }
    SECTION("degenerate input") {
        CHECK(planar({}, {}));
        CHECK_FALSE(planar({{0, 0}, {1, 0}}, {{0, 5}}));                 // no such vertex
        CHECK_FALSE(planar({{0, 0}}, {{0, 0}}));                         // a loop
        CHECK_FALSE(planar({{0, 0}, {0, 0}}, {{0, 1}}, 0));              // zero length
        CHECK_FALSE(planar({{0, 0}, {NAN, 0}}, {{0, 1}}));
    }
}

TEST_CASE("drawingIsPlanar: the grid agrees with the scans on a large drawing", "[angle-drawing]") {
    // A 30 x 30 lattice (1740 edges), then one vertex pushed across its neighbours.
    constexpr int n = 30;
    std::vector<vec2> p;
    std::vector<AngleEdge> edges;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) p.push_back({x, y});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            if (x + 1 < n) edges.push_back({y * n + x, y * n + x + 1, 0, 1, 1});
            if (y + 1 < n) edges.push_back({y * n + x, (y + 1) * n + x, kPi / 2, 1, 1});
        }
    // A long diagonal in a face-free corner: goes to the grid's list of long items.
    p.push_back({-1, 0});
    p.push_back({-31, 30});
    edges.push_back({n * n, n * n + 1, 3 * kPi / 4, 1, 50});
    CHECK(drawingIsPlanar(p, edges, 1e-6));
    std::vector<char> all(p.size(), 1);
    CHECK(drawingIsPlanar(p, edges, 1e-6, all));

    Rng rng(9);
    for (int trial = 0; trial < 40; ++trial) {
        std::vector<vec2> q = p;
        const int v = static_cast<int>(rng.below(n * n));
        q[v] += vec2{rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5)};
        bool anyMoved = true;
        for (int w = 0; w < static_cast<int>(q.size()); ++w) {
            std::vector<char> one(q.size(), 0);
            one[w] = 1;
            anyMoved = anyMoved && drawingIsPlanar(q, edges, 1e-6, one);
        }
        std::vector<char> justV(q.size(), 0);
        justV[v] = 1;
        INFO("trial " << trial << " vertex " << v);
        CHECK(drawingIsPlanar(q, edges, 1e-6) == anyMoved);
        CHECK(drawingIsPlanar(q, edges, 1e-6, justV) == anyMoved);
    }
    // The diagonal moved onto the lattice.
    std::vector<vec2> q = p;
    q[n * n] = {0.5, 0.5};
    CHECK_FALSE(drawingIsPlanar(q, edges, 1e-6));
}

TEST_CASE("equal seeds give equal drawings, different seeds different ones", "[angle-drawing]") {
    const Builder b = rectangle();
    const DrawingSettings st = canvas(0, 0, 10, 10);
    Rng r1(42), r2(42), r3(43);
    const DrawingResult a = drawAngleGraph(b.g, st, r1), c = drawAngleGraph(b.g, st, r2),
                        d = drawAngleGraph(b.g, st, r3);
    REQUIRE(a.accepted);
    REQUIRE(d.accepted);
    CHECK(a.moved == c.moved);
    CHECK(a.systems == c.systems);
    CHECK(a.samples == c.samples);
    REQUIRE(a.position.size() == c.position.size());
    for (std::size_t k = 0; k < a.position.size(); ++k) {
        CHECK(a.position[k].x == c.position[k].x);   // bit for bit
        CHECK(a.position[k].y == c.position[k].y);
    }
    CHECK(r1.next() == r2.next());   // the same number of draws
    bool differ = false;
    for (std::size_t k = 0; k < a.position.size(); ++k)
        differ = differ || a.position[k].x != d.position[k].x || a.position[k].y != d.position[k].y;
    CHECK(differ);
}

TEST_CASE("the random draws follow the documented order", "[angle-drawing]") {
    SECTION("target lengths by edge index, then the loose component's corner") {
        const Builder b = rectangle();
        Rng rng(77), replica(77);
        const DrawingResult r = drawAngleGraph(b.g, canvas(0, 0, 10, 10), rng);
        REQUIRE(r.accepted);
        REQUIRE(r.samples == 1);
        double t[4];
        for (double& x : t) x = replica.uniform(1, 3);
        const double width = (t[0] + t[1]) / 2, height = (t[2] + t[3]) / 2;
        const double x0 = replica.uniform(0, 10 - width), y0 = replica.uniform(0, 10 - height);
        const std::vector<vec2> p = drawn(b.g, r);
        CHECK(std::abs(p[0].x - x0) <= 1e-12);
        CHECK(std::abs(p[0].y - y0) <= 1e-12);
        CHECK(std::abs(p[2].x - (x0 + width)) <= 1e-12);
        CHECK(std::abs(p[2].y - (y0 + height)) <= 1e-12);
        CHECK(rng.next() == replica.next());
    }
    SECTION("no draw for an inconsistent system, one pick before the next") {
        Builder b;
        const int a = b.vertex(0, 0, false), c = b.vertex(4, 1, false), m = b.vertex(0, 0, true);
        b.edge(a, m, 0, 0.5, 5);
        b.edge(m, c, 0, 0.5, 5);
        DrawingSettings st = canvas(-10, -10, 10, 10);
        st.proposals = 1;
        Rng rng(3), replica(3);
        CHECK_FALSE(drawAngleGraph(b.g, st, rng).accepted);
        CHECK(rng.next() == replica.next());   // nothing drawn, not even a pick after the last system
        st.proposals = 2;
        for (std::uint64_t seed = 1; seed <= 8; ++seed) {
            Rng run(seed), pick(seed);
            const DrawingResult r = drawAngleGraph(b.g, st, run);
            REQUIRE(r.accepted);
            CHECK(r.moved[0] == (pick.below(2) == 0 ? a : c));
        }
    }
}

TEST_CASE("degenerate input gives no NaN and no crash", "[angle-drawing]") {
    const DrawingSettings st = canvas(0, 0, 10, 10);
    auto run = [&](const AngleGraph& g, const DrawingSettings& s) {
        Rng rng(1);
        const DrawingResult r = drawAngleGraph(g, s, rng);
        CHECK(allFinite(r));
        CHECK(r.moved.size() == r.position.size());
        if (!r.accepted) CHECK(r.moved.empty());
        return r;
    };
    SECTION("an empty graph: nothing to draw") {
        const DrawingResult r = run(AngleGraph{}, st);
        CHECK(r.accepted);
        CHECK(r.moved.empty());
    }
    SECTION("a free vertex without edges goes anywhere in the canvas") {
        Builder b;
        b.vertex(NAN, NAN, true);
        const DrawingResult r = run(b.g, st);
        REQUIRE(r.accepted);
        CHECK(r.position[0].x >= 0);
        CHECK(r.position[0].x <= 10);
        CHECK(r.position[0].y >= 0);
        CHECK(r.position[0].y <= 10);
        Rng other(2);
        CHECK(drawAngleGraph(b.g, st, other).position[0] != r.position[0]);
    }
    SECTION("a zero-length range") {
        Builder b;
        const int a = b.vertex(1, 1, false), m = b.vertex(1, 1, true);
        b.edge(a, m, 0, 0, 0);
        CHECK_FALSE(run(b.g, st).accepted);
    }
    SECTION("a loop on a free vertex") {
        Builder b;
        const int m = b.vertex(0, 0, true);
        b.edge(m, m, 0, 1, 2);
        CHECK_FALSE(run(b.g, st).accepted);
    }
    SECTION("bad numbers and indices") {
        Builder b;
        const int a = b.vertex(1, 1, false), m = b.vertex(0, 0, true);
        b.edge(a, m, NAN, 1, 2);
        CHECK_FALSE(run(b.g, st).accepted);
        b.g.edges[0] = {a, 7, 0, 1, 2};
        CHECK_FALSE(run(b.g, st).accepted);
        b.g.edges[0] = {a, m, 0, 1, INFINITY};
        CHECK_FALSE(run(b.g, st).accepted);
        b.g.edges[0] = {a, m, 0, 1, 2};
        b.g.position[a] = {NAN, 0};
        CHECK_FALSE(run(b.g, st).accepted);
    }
    SECTION("a canvas that is infinite, inverted or too small") {
        const Builder b = rectangle();
        CHECK_FALSE(run(b.g, canvas(-INFINITY, -INFINITY, INFINITY, INFINITY)).accepted);
        CHECK_FALSE(run(b.g, canvas(10, 10, 0, 0)).accepted);
        CHECK_FALSE(run(b.g, canvas(0, 0, 0.5, 0.5)).accepted);
    }
    SECTION("no systems or no samples allowed") {
        const Builder b = rectangle();
        DrawingSettings s = st;
        s.proposals = 0;
        CHECK(run(b.g, s).systems == 0);
        s.proposals = 3;
        s.samples = 0;
        const DrawingResult r = run(b.g, s);
        CHECK_FALSE(r.accepted);
        CHECK(r.samples == 0);
    }
    SECTION("parallel edges with the same angle between new vertices") {
        Builder b;
        const int p = b.vertex(0, 0, true), q = b.vertex(0, 0, true);
        b.edge(p, q, 0, 1, 2);
        b.edge(p, q, 0, 1, 2);
        CHECK_FALSE(run(b.g, st).accepted);   // they coincide
    }
}

TEST_CASE("a sampled length that a rigid edge fixes is drawn at that length", "[angle-drawing]") {
    // Merrell's framed box: the left side may be 1 to 5 long, the right one
    // is rigid at 1, so the left one is 1 too: no length is free, and the
    // kernel's rounding noise must not be fitted as if it were.
    Builder b;
    for (int i = 0; i < 4; ++i) b.vertex(0, 0, true);
    b.edge(1, 0, kPi / 2, 1, 5);
    b.edge(0, 2, 0, 1, 1);
    b.edge(1, 3, 0, 1, 1);
    b.edge(3, 2, kPi / 2, 1, 1);
    Rng rng(1);
    const DrawingResult r = drawAngleGraph(b.g, canvas(10, -16, 22, -4), rng);
    REQUIRE(r.accepted);
    CHECK(r.samples == 1);
    const auto p = drawn(b.g, r);
    for (const AngleEdge& e : b.g.edges) CHECK(std::abs(std::hypot(along(p, e).x, along(p, e).y) - 1) < 1e-9);
}

TEST_CASE("a component is not drawn inside a region of another area than its outside", "[angle-drawing]") {
    // A fixed 10 x 10 square of area 1 inside; the canvas is its inside, so
    // every place for a new triangle is within area 1.
    auto build = [](int triangleOutside) {
        Builder b;
        const int s0 = b.vertex(0, 0, false), s1 = b.vertex(10, 0, false), s2 = b.vertex(10, 10, false), s3 = b.vertex(0, 10, false);
        for (auto [from, to, angle] : std::vector<std::tuple<int, int, double>>{{s0, s1, 0}, {s1, s2, kPi / 2}, {s2, s3, kPi}, {s3, s0, -kPi / 2}}) {
            const int e = b.edge(from, to, angle, 10, 10, false);
            b.g.edges[e].left = 1;   // counter-clockwise: the inside is on the left
        }
        // A triangle whose outside (right of its counter-clockwise edges) is `triangleOutside`.
        const int t0 = b.vertex(0, 0, true), t1 = b.vertex(0, 0, true), t2 = b.vertex(0, 0, true);
        for (auto [from, to, angle] : std::vector<std::tuple<int, int, double>>{{t0, t1, 0}, {t1, t2, 3 * kPi / 4}, {t2, t0, -3 * kPi / 4}}) {
            const int e = b.edge(from, to, angle, 1, 2);
            b.g.edges[e].left = 2;
            b.g.edges[e].right = triangleOutside;
        }
        return b;
    };
    DrawingSettings s = canvas(0.5, 0.5, 9.5, 9.5);
    s.consistentAreas = true;
    Rng rng(3);
    CHECK_FALSE(drawAngleGraph(build(-1).g, s, rng).accepted);   // an island of "none" in area 1
    CHECK(drawAngleGraph(build(1).g, s, rng).accepted);          // a hole of area 2 in area 1
    s.consistentAreas = false;
    CHECK(drawAngleGraph(build(-1).g, s, rng).accepted);
    // Seen from the other side: a square of area 1 drawn around a fixed island of "none".
    CHECK(areasConsistent({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {6, 4}, {5, 5}},
                          {{0, 1, 0, 10, 10, 1, -1}, {1, 2, kPi / 2, 10, 10, 1, -1}, {2, 3, kPi, 10, 10, 1, -1}, {3, 0, -kPi / 2, 10, 10, 1, -1},
                           {4, 5, 0, 2, 2, 2, 1}, {5, 6, 3 * kPi / 4, 1, 2, 2, 1}, {6, 4, -3 * kPi / 4, 1, 2, 2, 1}},
                          {1, 1, 1, 1, 0, 0, 0}));
    CHECK_FALSE(areasConsistent({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {6, 4}, {5, 5}},
                                {{0, 1, 0, 10, 10, 1, -1}, {1, 2, kPi / 2, 10, 10, 1, -1}, {2, 3, kPi, 10, 10, 1, -1}, {3, 0, -kPi / 2, 10, 10, 1, -1},
                                 {4, 5, 0, 2, 2, 2, -1}, {5, 6, 3 * kPi / 4, 1, 2, 2, -1}, {6, 4, -3 * kPi / 4, 1, 2, 2, -1}},
                                {1, 1, 1, 1, 0, 0, 0}));
}
