// The spatial hash grids (runtime/engine/include/g2d/spatial_grid.hpp): small cases
// with exact answers, then random points and boxes against brute force
// through inserts, removals and moves, including queries larger than the
// table (which scan it) and boxes too big for the cells.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "g2d/spatial_grid.hpp"

using namespace g2d::rt;

namespace {

std::vector<std::uint32_t> idsWithin(const SpatialGrid& grid, vec3 centre, double radius) {
    std::vector<std::uint32_t> ids;
    grid.forEachWithin(centre, radius, [&](std::uint32_t id, vec3) { ids.push_back(id); });
    return ids;
}

std::vector<std::uint32_t> bruteWithin(const std::map<std::uint32_t, vec3>& points, vec3 centre, double radius) {
    std::vector<std::uint32_t> ids;
    for (const auto& [id, p] : points)
        if (glm::dot(p - centre, p - centre) <= radius * radius) ids.push_back(id);
    return ids;
}

std::vector<std::uint32_t> bruteOverlapping(const std::map<std::uint32_t, Aabb>& boxes, const Aabb& box) {
    std::vector<std::uint32_t> ids;
    for (const auto& [id, b] : boxes)
        if (overlaps(b, box)) ids.push_back(id);
    return ids;
}

}  // namespace

TEST_CASE("point grid: within a radius, closed, sorted by id", "[spatial_grid]") {
    SpatialGrid grid(1.0);
    grid.insert(7, {0.5, 0, 0});
    grid.insert(3, {-0.5, 0, 0});    // across the cell boundary at 0
    grid.insert(5, {0, 0, -0.0001});
    grid.insert(1, {3, 3, 3});
    CHECK(grid.size() == 4);
    CHECK(idsWithin(grid, {0, 0, 0}, 0.5) == std::vector<std::uint32_t>{3, 5, 7});  // 0.5 exactly is in
    CHECK(idsWithin(grid, {0, 0, 0}, 0.4999) == std::vector<std::uint32_t>{5});
    CHECK(idsWithin(grid, {0, 0, 0}, 0).empty());
    CHECK(idsWithin(grid, {0, 0, 0}, -1).empty());
    CHECK(idsWithin(grid, {0, 0, 0}, 100) == std::vector<std::uint32_t>{1, 3, 5, 7});
    std::vector<SpatialGrid::Hit> hits;
    grid.within({3, 3, 3.1}, 0.2, hits);
    REQUIRE(hits.size() == 1);
    CHECK(hits[0].id == 1);
    CHECK(hits[0].point == vec3(3, 3, 3));
}

TEST_CASE("point grid: coordinates beyond the cell range share the outermost cells", "[spatial_grid]") {
    SpatialGrid grid(1.0);
    grid.insert(1, {-1e12, 0, 0});
    grid.insert(2, {-1e12 + 1, 0, 0});
    grid.insert(3, {1e300, -1e300, 1e15});
    grid.insert(4, {0, 0, 0});
    CHECK(idsWithin(grid, {-1e12, 0, 0}, 0.5) == std::vector<std::uint32_t>{1});
    CHECK(idsWithin(grid, {-1e12, 0, 0}, 1) == std::vector<std::uint32_t>{1, 2});
    CHECK(idsWithin(grid, {1e300, -1e300, 1e15}, 1) == std::vector<std::uint32_t>{3});
    CHECK(idsWithin(grid, {0, 0, 0}, 1) == std::vector<std::uint32_t>{4});
    CHECK(grid.remove(1, {-1e12, 0, 0}));
    CHECK(idsWithin(grid, {-1e12, 0, 0}, 1) == std::vector<std::uint32_t>{2});
}

TEST_CASE("point grid: remove, move, clear", "[spatial_grid]") {
    SpatialGrid grid(0.5);
    grid.insert(1, {0, 0, 0});
    grid.insert(2, {0.1, 0, 0});
    CHECK_FALSE(grid.remove(3, {0, 0, 0}));    // no such id
    CHECK_FALSE(grid.remove(1, {10, 0, 0}));   // not where it was put
    CHECK(grid.move(2, {0.1, 0, 0}, {0.2, 0, 0}));  // within its cell
    CHECK(idsWithin(grid, {0.2, 0, 0}, 0.01) == std::vector<std::uint32_t>{2});
    CHECK(grid.move(2, {0.2, 0, 0}, {-5, 4, 2}));   // to another cell
    CHECK(idsWithin(grid, {0, 0, 0}, 1) == std::vector<std::uint32_t>{1});
    CHECK(idsWithin(grid, {-5, 4, 2}, 0) == std::vector<std::uint32_t>{2});
    CHECK_FALSE(grid.move(2, {0.2, 0, 0}, {1, 1, 1}));
    CHECK(grid.remove(1, {0, 0, 0}));
    CHECK_FALSE(grid.remove(1, {0, 0, 0}));
    CHECK(grid.size() == 1);
    // The callback may change the grid: the hits are collected first.
    grid.forEachWithin({-5, 4, 2}, 1, [&](std::uint32_t id, vec3 p) { CHECK(grid.remove(id, p)); });
    CHECK(grid.size() == 0);
    grid.insert(9, {1, 2, 3});
    grid.clear();
    CHECK(grid.size() == 0);
    CHECK(idsWithin(grid, {1, 2, 3}, 1).empty());
}

TEST_CASE("point grid: random points against brute force", "[spatial_grid]") {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> coord(-5, 5), radius(0, 1.5), unit(0, 1);
    const auto point = [&] { return vec3(coord(rng), coord(rng), coord(rng)); };
    for (double cell : {0.25, 1.0, 7.0}) {
        SpatialGrid grid(cell);
        if (cell == 1.0) grid.reserve(3000);  // sized up front: the same answers
        std::map<std::uint32_t, vec3> model;
        for (std::uint32_t id = 0; id < 3000; ++id) {
            // Some on a lattice, so on cell boundaries and coinciding.
            const vec3 p = id % 5 == 0 ? glm::floor(point()) * 0.5 : point();
            grid.insert(id * 7 % 3001, p);
            model[id * 7 % 3001] = p;
        }
        const auto compare = [&] {
            REQUIRE(grid.size() == model.size());
            for (int q = 0; q < 300; ++q) {
                const vec3 c = point();
                const double r = q % 50 == 0 ? 20 : radius(rng);
                CAPTURE(cell, q);
                REQUIRE(idsWithin(grid, c, r) == bruteWithin(model, c, r));
            }
        };
        compare();
        // Remove a third, move a third (some a little, some far), then re-check.
        for (auto it = model.begin(); it != model.end();) {
            const double roll = unit(rng);
            if (roll < 1.0 / 3) {
                REQUIRE(grid.remove(it->first, it->second));
                it = model.erase(it);
                continue;
            }
            if (roll < 2.0 / 3) {
                const vec3 to = unit(rng) < 0.5 ? it->second + vec3(0.01, -0.02, 0.03) : point();
                REQUIRE(grid.move(it->first, it->second, to));
                it->second = to;
            }
            ++it;
        }
        compare();
        for (std::uint32_t id = 5000; id < 6000; ++id) {
            const vec3 p = point();
            grid.insert(id, p);
            model[id] = p;
        }
        compare();
    }
}

TEST_CASE("point grid: answers do not depend on insertion order", "[spatial_grid]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(0, 3);
    std::vector<std::pair<std::uint32_t, vec3>> points;
    for (std::uint32_t id = 0; id < 2000; ++id) points.emplace_back(id, vec3(coord(rng), coord(rng), coord(rng)));
    SpatialGrid forward(0.3), backward(0.3);
    for (const auto& [id, p] : points) forward.insert(id, p);
    for (auto it = points.rbegin(); it != points.rend(); ++it) backward.insert(it->first, it->second);
    std::vector<SpatialGrid::Hit> a, b;
    for (const auto& [id, p] : points) {
        forward.within(p, 0.2, a);
        backward.within(p, 0.2, b);
        REQUIRE(a.size() == b.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
            REQUIRE(a[i].id == b[i].id);
            REQUIRE(a[i].point == b[i].point);
        }
        REQUIRE(std::is_sorted(a.begin(), a.end(), [](const auto& x, const auto& y) { return x.id < y.id; }));
    }
}

TEST_CASE("box grid: overlapping boxes, each once, in id order", "[spatial_grid]") {
    SpatialBoxGrid grid(1.0);
    grid.insert(4, {{0, 0, 0}, {2.5, 0.5, 0.5}});      // spans three cells
    grid.insert(2, {{3, 0, 0}, {3, 0, 0}});            // a point box
    grid.insert(9, {{-100, -100, -1}, {100, 100, 1}});  // too big for the cells
    std::vector<std::uint32_t> ids;
    grid.overlapping({{0.1, 0.1, 0.1}, {2.9, 0.2, 0.2}}, ids);
    CHECK(ids == std::vector<std::uint32_t>{4, 9});
    grid.overlapping({{2.5, 0, 0}, {3, 0, 0}}, ids);  // touching both small boxes
    CHECK(ids == std::vector<std::uint32_t>{2, 4, 9});
    grid.overlapping({{0, 0, 5}, {1, 1, 6}}, ids);
    CHECK(ids.empty());
    CHECK_FALSE(grid.remove(4, {{0, 0, 0}, {1, 1, 1}}));  // not the box it was inserted with
    CHECK(grid.remove(4, {{0, 0, 0}, {2.5, 0.5, 0.5}}));
    CHECK(grid.remove(9, {{-100, -100, -1}, {100, 100, 1}}));
    CHECK_FALSE(grid.remove(9, {{-100, -100, -1}, {100, 100, 1}}));
    grid.overlapping({{-1, -1, -1}, {4, 4, 4}}, ids);
    CHECK(ids == std::vector<std::uint32_t>{2});
    CHECK(grid.size() == 1);
    std::vector<std::uint32_t> seen;
    grid.forEachOverlapping({{3, 0, 0}, {3, 0, 0}}, [&](std::uint32_t id) { seen.push_back(id); });
    CHECK(seen == std::vector<std::uint32_t>{2});
}

TEST_CASE("box grid: random boxes against brute force", "[spatial_grid]") {
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> coord(-10, 10), unit(0, 1);
    const auto randomBox = [&](double maxSize) {
        const vec3 lo(coord(rng), coord(rng), coord(rng));
        return Aabb{lo, lo + vec3(unit(rng), unit(rng), unit(rng)) * maxSize};
    };
    SpatialBoxGrid grid(1.0);
    std::map<std::uint32_t, Aabb> model;
    for (std::uint32_t id = 0; id < 3000; ++id) {
        // Mostly small (edges and faces), a few spanning many cells (walls).
        const Aabb box = randomBox(id % 100 == 0 ? 15.0 : 1.5);
        grid.insert(id * 13 % 3001, box);
        model[id * 13 % 3001] = box;
    }
    const auto compare = [&] {
        REQUIRE(grid.size() == model.size());
        std::vector<std::uint32_t> ids;
        for (int q = 0; q < 300; ++q) {
            const Aabb box = randomBox(q % 60 == 0 ? 40.0 : 2.0);
            grid.overlapping(box, ids);
            CAPTURE(q);
            REQUIRE(ids == bruteOverlapping(model, box));
        }
    };
    compare();
    for (auto it = model.begin(); it != model.end();) {
        if (unit(rng) < 0.4) {
            REQUIRE(grid.remove(it->first, it->second));
            it = model.erase(it);
        } else {
            ++it;
        }
    }
    compare();
    for (std::uint32_t id = 4000; id < 5000; ++id) {
        const Aabb box = randomBox(id % 50 == 0 ? 15.0 : 1.5);
        grid.insert(id, box);
        model[id] = box;
    }
    compare();
    grid.clear();
    model.clear();
    compare();
}

TEST_CASE("a million points: each finds itself", "[spatial_grid]") {
    // The scale merging needs (no timing here: it runs in well under a
    // second in a release build).
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> coord(0, 100);
    std::vector<vec3> points(1000000);
    for (vec3& p : points) p = {coord(rng), coord(rng), coord(rng)};
    SpatialGrid grid(0.2);
    for (std::uint32_t id = 0; id < points.size(); ++id) grid.insert(id, points[id]);
    std::vector<SpatialGrid::Hit> hits;
    std::size_t found = 0;
    for (std::uint32_t id = 0; id < points.size(); ++id) {
        grid.within(points[id], 1e-9, hits);
        found += hits.size() == 1 && hits[0].id == id;
    }
    CHECK(found == points.size());
}
