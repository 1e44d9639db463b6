#include "g2d/near_queries.hpp"

#include <algorithm>
#include <cmath>

namespace g2d::rt {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

// A point lies in a disk, with room for the rounding of the disk's own
// distance test (a superset is safe: it costs a revisit).
double slack(double radius) { return radius * (1 + 1e-9) + 1e-12; }
bool inDisk(vec3 p, vec3 centre, double radius) {
    const vec3 d = p - centre;
    const double r = slack(radius);
    return d.x * d.x + d.y * d.y + d.z * d.z <= r * r;
}

// A grid's cell for queries of about this radius (a point query then reads a few cells).
double cellFor(double radius) { return radius > 0 && std::isfinite(radius) ? 2 * radius : 1.0; }

}  // namespace

void NearQueries::start(const Graph& g, const std::vector<std::vector<int>>& nearKinds, const std::vector<int>& joinKinds) {
    *this = NearQueries{};
    rules_.resize(nearKinds.size());
    for (std::size_t r = 0; r < nearKinds.size(); ++r)
        for (int kind : nearKinds[r]) {
            rules_[r].emplace_back().kind = kind;
            if (!pointsOf(kind)) points_.emplace_back().kind = kind;
        }
    for (int kind : joinKinds) {
        if (kind < 0) any_.emplace(Points{}).kind = -1;   // emplace(): clang finds Points not default-constructible
        else if (!pointsOf(kind)) points_.emplace_back().kind = kind;
    }
    if (points_.empty() && !any_) return;
    started_ = true;
    for (const Points& p : points_)
        for (NodeId n : g.nodesOfKind(p.kind)) index(n, p.kind, g.pos3(n));
    if (any_)
        for (NodeId n : g.allNodes()) syncAny(g, n);
}

// Keeps node n's place in the index of every node.
void NearQueries::syncAny(const Graph& g, NodeId n) {
    if (n >= inAny_.size()) {
        inAny_.resize(n + 1 + n / 2, 0);
        anyAt_.resize(inAny_.size());
    }
    const bool alive = g.nodeAlive(n);
    const vec3 p = alive ? g.pos3(n) : vec3{};
    if (any_->grid) {
        if (inAny_[n] && !alive) any_->grid->remove(n, anyAt_[n]);
        else if (inAny_[n]) any_->grid->move(n, anyAt_[n], p);
        else if (alive) any_->grid->insert(n, p);
    }
    inAny_[n] = alive ? 1 : 0;
    anyAt_[n] = p;
}

std::span<const NodeId> NearQueries::nodesAround(const Graph& g, int kind, vec3 centre, double radius) {
    Points* pts = kind < 0 ? (any_ ? &*any_ : nullptr) : pointsOf(kind);
    if (!started_ || g.scope() || !pts || !std::isfinite(radius)) return every(g, kind);
    if (!(radius >= 0)) return {};   // no distance is below a negative radius
    if (!pts->grid) {   // made at the first query, its cell from that radius
        const std::vector<vec3>& at = kind < 0 ? anyAt_ : at_;
        pts->grid.emplace(cellFor(radius));
        for (NodeId n : every(g, kind)) pts->grid->insert(n, at[n]);
    }
    pts->grid->within(centre, slack(radius), hits_);
    scratch_.clear();
    for (const auto& h : hits_) scratch_.push_back(h.id);
    return scratch_;
}

// The nodes of `kind`, or every node for -1.
std::span<const NodeId> NearQueries::every(const Graph& g, int kind) {
    if (kind >= 0) return g.nodesOfKind(kind);
    scratch_.clear();
    for (NodeId n : g.allNodes()) scratch_.push_back(n);
    return scratch_;
}

void NearQueries::stop() { *this = NearQueries{}; }

NearQueries::Points* NearQueries::pointsOf(int kind) {
    for (Points& p : points_)
        if (p.kind == kind) return &p;
    return nullptr;
}

void NearQueries::index(NodeId n, int kind, vec3 p) {
    if (n >= kindOf_.size()) {
        kindOf_.resize(n + 1 + n / 2, -1);
        at_.resize(kindOf_.size());
    }
    Points* pts = pointsOf(kind);
    if (pts->grid) {
        if (kindOf_[n] == kind) pts->grid->move(n, at_[n], p);
        else pts->grid->insert(n, p);
    }
    kindOf_[n] = kind;
    at_[n] = p;
}

void NearQueries::unindex(NodeId n) {
    if (Points* pts = pointsOf(kindOf_[n]); pts->grid) pts->grid->remove(n, at_[n]);
    kindOf_[n] = -1;
}

void NearQueries::sync(const Graph& g) {
    probes_.clear();
    if (!started_) return;
    for (NodeId n : g.changedNodes()) {
        if (any_) syncAny(g, n);
        const int was = n < kindOf_.size() ? kindOf_[n] : -1;
        const bool alive = g.nodeAlive(n);
        const int kind = alive && pointsOf(g.nodeKind(n)) ? g.nodeKind(n) : -1;
        if (was < 0 && kind < 0) continue;
        // A node that changed only its edges changes no disk's outcome
        // (lower::nearNegative: the conditions read no incidences).
        if (was >= 0 && was == kind && !g.changedItself(n, true)) continue;
        if (was >= 0) probes_.push_back({was, at_[n]});
        if (was >= 0 && was != kind) unindex(n);
        if (kind < 0) continue;
        const vec3 p = g.pos3(n);
        if (was != kind || !(p == at_[n])) probes_.push_back({kind, p});
        index(n, kind, p);
    }
}

std::span<const NodeId> NearQueries::nodesNear(const Graph& g, std::size_t rule, int near, NodeId key, int kind,
                                               vec3 centre, double radius) {
    if (!started_ || g.scope() || rule >= rules_.size() || near < 0 || static_cast<std::size_t>(near) >= rules_[rule].size())
        return g.nodesOfKind(kind);
    if (!(radius >= 0)) return {};   // no distance is below a negative or NaN radius
    record(rules_[rule][static_cast<std::size_t>(near)], key, centre, radius);
    Points* pts = pointsOf(kind);
    if (!std::isfinite(radius)) return g.nodesOfKind(kind);
    if (!pts->grid) {
        pts->grid.emplace(cellFor(radius));
        for (NodeId n : g.nodesOfKind(kind)) pts->grid->insert(n, at_[n]);
    }
    pts->grid->within(centre, slack(radius), hits_);
    scratch_.clear();
    for (const auto& h : hits_) scratch_.push_back(h.id);
    return scratch_;
}

void NearQueries::record(Disks& d, NodeId key, vec3 centre, double radius) {
    if (key >= d.firstOfKey.size()) d.firstOfKey.resize(key + 1 + key / 2, kNone);
    for (std::uint32_t i = d.firstOfKey[key]; i != kNone; i = d.disks[i].nextOfKey)
        if (d.disks[i].centre == centre && d.disks[i].radius == radius) return;   // the same test again
    std::uint32_t id;
    if (!d.freeDisks.empty()) {
        id = d.freeDisks.back();
        d.freeDisks.pop_back();
    } else {
        id = static_cast<std::uint32_t>(d.disks.size());
        d.disks.emplace_back();
    }
    Disk& disk = d.disks[id];
    disk = {centre, radius, inflated({centre, centre}, slack(radius)), key, d.firstOfKey[key], false};
    d.firstOfKey[key] = id;
    if (!std::isfinite(radius)) {
        disk.everywhere = true;
        d.everywhere.push_back(id);
        return;
    }
    if (!d.grid) d.grid.emplace(cellFor(radius));
    d.grid->insert(id, disk.box);
}

void NearQueries::remove(Disks& d, std::uint32_t id) {
    Disk& disk = d.disks[id];
    if (disk.everywhere) d.everywhere.erase(std::find(d.everywhere.begin(), d.everywhere.end(), id));
    else d.grid->remove(id, disk.box);
    d.freeDisks.push_back(id);
}

void NearQueries::forget(std::size_t rule, NodeId key) {
    if (rule >= rules_.size()) return;
    for (Disks& d : rules_[rule]) {
        if (key >= d.firstOfKey.size()) continue;
        for (std::uint32_t i = d.firstOfKey[key]; i != kNone; i = d.disks[i].nextOfKey) remove(d, i);
        d.firstOfKey[key] = kNone;
    }
}

void NearQueries::forgetRule(std::size_t rule) {
    if (rule >= rules_.size()) return;
    for (Disks& d : rules_[rule]) {
        const int kind = d.kind;
        d = Disks{};
        d.kind = kind;
    }
}

void NearQueries::touchedKeys(std::size_t rule, std::vector<NodeId>& out) {
    if (rule >= rules_.size() || probes_.empty()) return;
    for (Disks& d : rules_[rule]) {
        for (const Probe& p : probes_) {
            if (p.kind != d.kind) continue;
            if (d.grid) {
                d.grid->overlapping({p.at, p.at}, ids_);
                for (std::uint32_t i : ids_)
                    if (inDisk(p.at, d.disks[i].centre, d.disks[i].radius)) out.push_back(d.disks[i].key);
            }
            for (std::uint32_t i : d.everywhere) out.push_back(d.disks[i].key);
        }
    }
}

}  // namespace g2d::rt
