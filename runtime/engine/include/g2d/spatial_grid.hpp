#pragma once
// Uniform hash grids over 3D space: the k-d tree's job in merging (§3.1.2.1:
// nodes within a small distance) and candidate pairs for the intersection
// tests (§3.2). A hash grid rather than a k-d tree (the thesis's GEL one, or
// Debian's nanoflann, whose dynamic index is a forest of static trees with
// removal by marking): O(1) insert, remove and move as nodes are made,
// merged and edited every step, no rebuilds, and the queries are small (a
// merge tolerance, one primitive's box).
//
// Cells are cubes of a size the caller chooses; only occupied cells are
// stored (open addressing, linear probing). A query visits the cells its box
// overlaps (every occupied cell instead, when that is fewer), so pick the
// cell size near the query size: at least twice the radius keeps a point
// query to 8 cells.
//
// Results come sorted by id, each id once, whatever the insertion order or
// table layout: merging must be identical run to run. They are collected
// before the callback runs, so the callback may change the grid. Positions
// must be finite; coordinates beyond 2^30 cells share the outermost cells
// (still correct, only slower). Queries are const and keep no scratch state,
// so threads may query one grid at once.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "g2d/vec_math.hpp"

namespace g2d::rt {

// A closed axis-aligned box.
struct Aabb {
    vec3 lo, hi;
};
Aabb boundsOf(std::span<const vec3> points);  // points must not be empty
Aabb inflated(const Aabb& box, double margin);
bool overlaps(const Aabb& a, const Aabb& b);  // closed: touching boxes overlap

namespace detail {

// Occupied cells -> the head of each cell's list (an index into the grid's
// own entries). Cells whose list empties stay until the next rebuild.
class CellTable {
public:
    static constexpr std::uint32_t kNone = 0xffffffffu;
    struct Cell {
        std::int32_t x, y, z;
        std::uint32_t head;
    };
    const std::uint32_t* find(std::int32_t x, std::int32_t y, std::int32_t z) const;
    std::uint32_t* find(std::int32_t x, std::int32_t y, std::int32_t z) {
        return const_cast<std::uint32_t*>(static_cast<const CellTable*>(this)->find(x, y, z));
    }
    // The cell's head, added (kNone) if missing; valid until the next call.
    std::uint32_t& findOrAdd(std::int32_t x, std::int32_t y, std::int32_t z);
    std::size_t slotsInUse() const { return used_; }
    void reserve(std::size_t cells);
    const std::vector<Cell>& slots() const { return slots_; }  // unused slots have x == kUnused
    void clear();
    static constexpr std::int32_t kUnused = INT32_MIN;

private:
    void rebuild(std::size_t cells);
    std::vector<Cell> slots_;
    std::size_t used_ = 0;
};

}  // namespace detail

// Points under ids (each id at most once).
class SpatialGrid {
public:
    explicit SpatialGrid(double cellSize);  // > 0
    double cellSize() const { return cell_; }
    std::size_t size() const { return size_; }

    // Room for `points` points in distinct cells without rehashing.
    void reserve(std::size_t points);
    void insert(std::uint32_t id, vec3 point);
    // `point` is where the id was inserted or last moved to; false if absent.
    bool remove(std::uint32_t id, vec3 point);
    bool move(std::uint32_t id, vec3 from, vec3 to);
    void clear();

    struct Hit {
        std::uint32_t id;
        vec3 point;
    };
    // The points with ‖point − centre‖ <= radius, sorted by id, into `out`
    // (cleared first).
    void within(vec3 centre, double radius, std::vector<Hit>& out) const;
    // f(id, point) for each of within()'s hits, in id order.
    template <class F>
    void forEachWithin(vec3 centre, double radius, F&& f) const {
        std::vector<Hit> hits;
        within(centre, radius, hits);
        for (const Hit& hit : hits) f(hit.id, hit.point);
    }

private:
    struct Entry {
        vec3 point;
        std::uint32_t id, next;
    };
    double cell_;
    detail::CellTable cells_;
    std::vector<Entry> entries_;
    std::uint32_t freeEntry_ = detail::CellTable::kNone;
    std::size_t size_ = 0;
};

// Boxes under ids (each id at most once), e.g. the bounds of edges and faces.
// A box is listed in every cell it overlaps; one that would span more than
// kMaxCells cells (a big wall among small twigs) goes to a list every query
// checks instead.
class SpatialBoxGrid {
public:
    static constexpr double kMaxCells = 64;
    explicit SpatialBoxGrid(double cellSize);  // > 0
    double cellSize() const { return cell_; }
    std::size_t size() const { return size_; }

    void insert(std::uint32_t id, const Aabb& box);
    // `box` must be the one inserted under `id`; false if absent.
    bool remove(std::uint32_t id, const Aabb& box);
    void clear();

    // The ids whose boxes overlap `box`, sorted, each once, into `out`
    // (cleared first).
    void overlapping(const Aabb& box, std::vector<std::uint32_t>& out) const;
    template <class F>
    void forEachOverlapping(const Aabb& box, F&& f) const {
        std::vector<std::uint32_t> ids;
        overlapping(box, ids);
        for (std::uint32_t id : ids) f(id);
    }

private:
    // A box in one cell's list: the box is copied into each of its cells, so
    // a query reads one record per candidate rather than chasing an index.
    struct Link {
        Aabb box;
        std::uint32_t id, next;
    };
    double cell_;
    detail::CellTable cells_;
    std::vector<Link> links_;
    std::vector<std::pair<std::uint32_t, Aabb>> big_;  // boxes too big for the cells
    std::uint32_t freeLink_ = detail::CellTable::kNone;
    std::size_t size_ = 0;
};

}  // namespace g2d::rt
