#pragma once
// Negative conditions asking for a node near a point (RuleInfo::nearKinds,
// lower/near_negative.hpp): `not { o: K; where distance(o.pos, P) < R; }`.
//
// Searching: the nodes of each kind such a condition asks for sit in a
// spatial hash grid (spatial_grid.hpp), kept up to date with each step's
// changes, so a test reads the nodes near P instead of every K node.
//
// Repair: each test also records its disk (P, R) under a node of the match
// (the key: the first that P or R reads, lower::NearNegative::key). After a step, a K node that came, went, moved or was
// written can change the outcome only for the disks it lies in, before or
// after: their keys are revisited as if they had changed themselves, and no
// other match of the rule needs a search. A disk is forgotten when its key
// is revisited (every match binding the key is then tested again, recording
// afresh) or the rule is searched in full. A disk left behind by a match
// that lost another of its nodes stays until then, which costs a revisit,
// never a missed match.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/spatial_grid.hpp"

namespace g2d::rt {

class NearQueries {
public:
    // Follows `g` for the rules' conditions (`nearKinds` per rule; empty for
    // a rule whose matches are not kept over the whole graph).
    // `joinKinds`: the kinds positive searches look up near a point
    // (RuleInfo::joinKinds, -1: any node), indexed alike.
    void start(const Graph& g, const std::vector<std::vector<int>>& nearKinds, const std::vector<int>& joinKinds = {});
    bool started() const { return started_; }
    void stop();   // forgets everything (the derivation is over)
    // After a step, before its changes are forgotten: brings the index up to
    // date and keeps the changed nodes' old and new places for touchedKeys().
    void sync(const Graph& g);

    // The nodes of `kind` within `radius` of `centre` (at least: the caller
    // tests the distance), by id; with the index unstarted, or in a compound
    // scope, every node of the kind. Records the disk for repair under `key`.
    // Valid until the next call.
    std::span<const NodeId> nodesNear(const Graph& g, std::size_t rule, int near, NodeId key, int kind, vec3 centre,
                                      double radius);

    // The nodes of `kind` (-1: any) within `radius` of `centre` (at least),
    // by id, recording nothing: a pattern piece joined to bound nodes by
    // distance (lower::nearJoin). Every such node when the kind is not
    // indexed, or in a compound scope. Valid until the next call.
    std::span<const NodeId> nodesAround(const Graph& g, int kind, vec3 centre, double radius);

    // Appends the keys of `rule`'s disks that a node synced last lies in.
    void touchedKeys(std::size_t rule, std::vector<NodeId>& out);
    // Forgets `key`'s disks (it is about to be revisited), or all the rule's.
    void forget(std::size_t rule, NodeId key);
    void forgetRule(std::size_t rule);

private:
    struct Disk {
        vec3 centre;
        double radius;
        Aabb box;
        NodeId key;
        std::uint32_t nextOfKey;   // the key's next disk
        bool everywhere;           // in Disks::everywhere rather than the grid
    };
    // One condition's disks.
    struct Disks {
        int kind = -1;
        std::optional<SpatialBoxGrid> grid;     // made at the first finite disk, its cell from that disk
        std::vector<Disk> disks;
        std::vector<std::uint32_t> everywhere;  // disks too big for any grid (an infinite radius)
        std::vector<std::uint32_t> freeDisks;
        std::vector<std::uint32_t> firstOfKey;  // by node id
    };
    // The nodes of one kind.
    struct Points {
        int kind = -1;
        std::optional<SpatialGrid> grid;        // made at the first finite query, its cell from that radius
    };
    struct Probe {
        int kind;
        vec3 at;
    };

    Points* pointsOf(int kind);
    void index(NodeId n, int kind, vec3 p);
    void unindex(NodeId n);
    void syncAny(const Graph& g, NodeId n);
    std::span<const NodeId> every(const Graph& g, int kind);
    void record(Disks& d, NodeId key, vec3 centre, double radius);
    void remove(Disks& d, std::uint32_t disk);

    bool started_ = false;
    std::vector<Points> points_;
    std::vector<std::vector<Disks>> rules_;   // per rule, per condition
    std::vector<int> kindOf_;                 // by node id: the kind it is indexed under (-1: none)
    std::vector<vec3> at_;                    // by node id: where it is indexed
    std::optional<Points> any_;               // every node, for joins of wildcards
    std::vector<char> inAny_;                 // by node id: indexed in any_
    std::vector<vec3> anyAt_;                 // by node id: where, in any_
    std::vector<Probe> probes_;               // the last sync's changed places
    std::vector<NodeId> scratch_;
    std::vector<SpatialGrid::Hit> hits_;
    std::vector<std::uint32_t> ids_;
};

// A copy of a lookup's nodes (generated joins keep theirs while searching on).
inline std::vector<NodeId> asVector(std::span<const NodeId> nodes) { return {nodes.begin(), nodes.end()}; }

}  // namespace g2d::rt
