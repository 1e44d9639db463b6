#include "g2d/spatial_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace g2d::rt {

Aabb boundsOf(std::span<const vec3> points) {
    Aabb box{points[0], points[0]};
    for (const vec3& p : points) {
        box.lo = glm::min(box.lo, p);
        box.hi = glm::max(box.hi, p);
    }
    return box;
}

Aabb inflated(const Aabb& box, double margin) { return {box.lo - vec3(margin), box.hi + vec3(margin)}; }

bool overlaps(const Aabb& a, const Aabb& b) {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
           b.lo.z <= a.hi.z;
}

namespace detail {

namespace {
std::size_t hashOf(std::int32_t x, std::int32_t y, std::int32_t z) {
    std::uint64_t h = std::uint64_t{static_cast<std::uint32_t>(x)} * 0x9E3779B97F4A7C15ull;
    h ^= std::uint64_t{static_cast<std::uint32_t>(y)} * 0xC2B2AE3D27D4EB4Full;
    h ^= std::uint64_t{static_cast<std::uint32_t>(z)} * 0x165667B19E3779F9ull;
    h ^= h >> 32;
    h *= 0xD6E8FEB86659FD93ull;
    return static_cast<std::size_t>(h ^ (h >> 32));
}
}  // namespace

const std::uint32_t* CellTable::find(std::int32_t x, std::int32_t y, std::int32_t z) const {
    if (slots_.empty()) return nullptr;
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = hashOf(x, y, z) & mask;; i = (i + 1) & mask) {
        const Cell& cell = slots_[i];
        if (cell.x == kUnused) return nullptr;
        if (cell.x == x && cell.y == y && cell.z == z) return &cell.head;
    }
}

std::uint32_t& CellTable::findOrAdd(std::int32_t x, std::int32_t y, std::int32_t z) {
    if (std::uint32_t* head = find(x, y, z)) return *head;
    if ((used_ + 1) * 2 > slots_.size()) {
        std::size_t live = 1;
        for (const Cell& cell : slots_) live += cell.x != kUnused && cell.head != kNone;
        rebuild(live);
    }
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = hashOf(x, y, z) & mask;
    while (slots_[i].x != kUnused) i = (i + 1) & mask;
    slots_[i] = {x, y, z, kNone};
    ++used_;
    return slots_[i].head;
}

// Keeps only the cells that hold something, in a table with room for
// `cells` at a load of 1/4 (it grows at 1/2).
void CellTable::rebuild(std::size_t cells) {
    std::vector<Cell> old;
    old.swap(slots_);
    slots_.assign(std::max<std::size_t>(16, std::bit_ceil(4 * cells)), Cell{kUnused, 0, 0, kNone});
    used_ = 0;
    for (const Cell& cell : old)
        if (cell.x != kUnused && cell.head != kNone) findOrAdd(cell.x, cell.y, cell.z) = cell.head;
}

void CellTable::reserve(std::size_t cells) {
    if (4 * cells > slots_.size()) rebuild(std::max(cells, used_));
}

void CellTable::clear() {
    slots_.clear();
    used_ = 0;
}

}  // namespace detail

namespace {

using detail::CellTable;

// Cell coordinates, clamped well inside int32 so kUnused is never one (NaN
// goes to the lowest cell).
constexpr double kCellLimit = 1 << 30;
std::int32_t cellCoord(double v, double cell) {
    const double c = std::floor(v / cell);
    if (!(c > -kCellLimit)) return static_cast<std::int32_t>(-kCellLimit);
    if (!(c < kCellLimit)) return static_cast<std::int32_t>(kCellLimit);
    return static_cast<std::int32_t>(c);
}

struct CellRange {
    std::int32_t lo[3], hi[3];
    double count() const {
        double n = 1;
        for (int k = 0; k < 3; ++k) n *= double(hi[k]) - double(lo[k]) + 1;
        return n;
    }
    bool holds(const CellTable::Cell& c) const {
        return c.x >= lo[0] && c.x <= hi[0] && c.y >= lo[1] && c.y <= hi[1] && c.z >= lo[2] && c.z <= hi[2];
    }
};

CellRange rangeOf(const Aabb& box, double cell) {
    CellRange r{};
    for (int k = 0; k < 3; ++k) {
        r.lo[k] = cellCoord(box.lo[k], cell);
        r.hi[k] = cellCoord(box.hi[k], cell);
    }
    return r;
}

// f(head) for each occupied cell of the range: by lookup, or by a scan of
// the table when that is shorter.
template <class F>
void forEachCellIn(const CellTable& cells, const CellRange& r, F&& f) {
    if (r.count() > double(cells.slotsInUse())) {
        for (const CellTable::Cell& cell : cells.slots())
            if (cell.x != CellTable::kUnused && cell.head != CellTable::kNone && r.holds(cell)) f(cell.head);
        return;
    }
    for (std::int32_t x = r.lo[0]; x <= r.hi[0]; ++x)
        for (std::int32_t y = r.lo[1]; y <= r.hi[1]; ++y)
            for (std::int32_t z = r.lo[2]; z <= r.hi[2]; ++z)
                if (const std::uint32_t* head = cells.find(x, y, z); head && *head != CellTable::kNone) f(*head);
}

}  // namespace

// --- SpatialGrid ---

SpatialGrid::SpatialGrid(double cellSize) : cell_(cellSize) {}

void SpatialGrid::reserve(std::size_t points) {
    cells_.reserve(points);
    entries_.reserve(points);
}

void SpatialGrid::insert(std::uint32_t id, vec3 point) {
    std::uint32_t index = freeEntry_;
    if (index != CellTable::kNone) {
        freeEntry_ = entries_[index].next;
    } else {
        index = static_cast<std::uint32_t>(entries_.size());
        entries_.emplace_back();
    }
    std::uint32_t& head = cells_.findOrAdd(cellCoord(point.x, cell_), cellCoord(point.y, cell_), cellCoord(point.z, cell_));
    entries_[index] = {point, id, head};
    head = index;
    ++size_;
}

bool SpatialGrid::remove(std::uint32_t id, vec3 point) {
    std::uint32_t* link = cells_.find(cellCoord(point.x, cell_), cellCoord(point.y, cell_), cellCoord(point.z, cell_));
    if (!link) return false;
    for (; *link != CellTable::kNone; link = &entries_[*link].next) {
        Entry& entry = entries_[*link];
        if (entry.id != id) continue;
        const std::uint32_t index = *link;
        *link = entry.next;
        entry.next = freeEntry_;
        freeEntry_ = index;
        --size_;
        return true;
    }
    return false;
}

bool SpatialGrid::move(std::uint32_t id, vec3 from, vec3 to) {
    const auto same = [&](int k) { return cellCoord(from[k], cell_) == cellCoord(to[k], cell_); };
    if (same(0) && same(1) && same(2)) {
        const std::uint32_t* head = cells_.find(cellCoord(from.x, cell_), cellCoord(from.y, cell_), cellCoord(from.z, cell_));
        for (std::uint32_t i = head ? *head : CellTable::kNone; i != CellTable::kNone; i = entries_[i].next)
            if (entries_[i].id == id) {
                entries_[i].point = to;
                return true;
            }
        return false;
    }
    if (!remove(id, from)) return false;
    insert(id, to);
    return true;
}

void SpatialGrid::clear() {
    cells_.clear();
    entries_.clear();
    freeEntry_ = CellTable::kNone;
    size_ = 0;
}

void SpatialGrid::within(vec3 centre, double radius, std::vector<Hit>& out) const {
    out.clear();
    if (!(radius >= 0) || size_ == 0) return;
    const double r2 = radius * radius;
    forEachCellIn(cells_, rangeOf(inflated({centre, centre}, radius), cell_), [&](std::uint32_t head) {
        for (std::uint32_t i = head; i != CellTable::kNone; i = entries_[i].next) {
            const vec3 d = entries_[i].point - centre;
            if (glm::dot(d, d) <= r2) out.push_back({entries_[i].id, entries_[i].point});
        }
    });
    std::sort(out.begin(), out.end(), [](const Hit& a, const Hit& b) { return a.id < b.id; });
}

// --- SpatialBoxGrid ---

SpatialBoxGrid::SpatialBoxGrid(double cellSize) : cell_(cellSize) {}

void SpatialBoxGrid::insert(std::uint32_t id, const Aabb& box) {
    ++size_;
    const CellRange r = rangeOf(box, cell_);
    if (r.count() > kMaxCells) {
        big_.emplace_back(id, box);
        return;
    }
    for (std::int32_t x = r.lo[0]; x <= r.hi[0]; ++x)
        for (std::int32_t y = r.lo[1]; y <= r.hi[1]; ++y)
            for (std::int32_t z = r.lo[2]; z <= r.hi[2]; ++z) {
                std::uint32_t link = freeLink_;
                if (link != CellTable::kNone) {
                    freeLink_ = links_[link].next;
                } else {
                    link = static_cast<std::uint32_t>(links_.size());
                    links_.emplace_back();
                }
                std::uint32_t& head = cells_.findOrAdd(x, y, z);
                links_[link] = {box, id, head};
                head = link;
            }
}

bool SpatialBoxGrid::remove(std::uint32_t id, const Aabb& box) {
    // The same box too: with another, the cells searched would not be the
    // ones it is listed in.
    const auto matches = [&](std::uint32_t otherId, const Aabb& other) {
        return otherId == id && other.lo == box.lo && other.hi == box.hi;
    };
    const CellRange r = rangeOf(box, cell_);
    if (r.count() > kMaxCells) {
        const auto at = std::find_if(big_.begin(), big_.end(), [&](const auto& b) { return matches(b.first, b.second); });
        if (at == big_.end()) return false;
        *at = big_.back();
        big_.pop_back();
        --size_;
        return true;
    }
    bool found = false;
    for (std::int32_t x = r.lo[0]; x <= r.hi[0]; ++x)
        for (std::int32_t y = r.lo[1]; y <= r.hi[1]; ++y)
            for (std::int32_t z = r.lo[2]; z <= r.hi[2]; ++z) {
                std::uint32_t* link = cells_.find(x, y, z);
                while (link && *link != CellTable::kNone && !matches(links_[*link].id, links_[*link].box))
                    link = &links_[*link].next;
                if (!link || *link == CellTable::kNone) return false;  // the first cell already, as each holds it
                const std::uint32_t freed = *link;
                *link = links_[freed].next;
                links_[freed].next = freeLink_;
                freeLink_ = freed;
                found = true;
            }
    size_ -= found;
    return found;
}

void SpatialBoxGrid::clear() {
    cells_.clear();
    links_.clear();
    big_.clear();
    freeLink_ = CellTable::kNone;
    size_ = 0;
}

void SpatialBoxGrid::overlapping(const Aabb& box, std::vector<std::uint32_t>& out) const {
    out.clear();
    forEachCellIn(cells_, rangeOf(box, cell_), [&](std::uint32_t head) {
        for (std::uint32_t i = head; i != CellTable::kNone; i = links_[i].next)
            if (overlaps(links_[i].box, box)) out.push_back(links_[i].id);
    });
    for (const auto& [id, b] : big_)
        if (overlaps(b, box)) out.push_back(id);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace g2d::rt
