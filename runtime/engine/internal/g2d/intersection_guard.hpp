#pragma once
// G^3's intersection tests (Laganeckiene 2012, §3.2) for a command that only
// adds elements (a rule with `intersect`: Create edge, Create face). After
// each application, what it added is tested against every edge and face of
// the graph (the step's earlier, kept additions included): an edge is a
// segment, thick by its end nodes' radii unless it bounds a face; a face is
// its triangulation (geometry3.hpp). An application whose additions
// intersect anything is undone — its faces, edges and nodes removed — as if
// it had not been applied. Touching is not intersecting: elements that share
// a node or a side meet there, and the tests are open there.
//
// Candidates come from a grid of boxes (spatial_grid.hpp) built when the
// step begins and grown with every addition kept.
#include <array>
#include <optional>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/spatial_grid.hpp"

namespace g2d::rt {

class IntersectionGuard {
public:
    // Node, edge and face capacities (ids are never reused: an application
    // added the ids between the capacities before and after it).
    using Capacities = std::array<std::size_t, 3>;
    static Capacities capacities(const Graph& g) { return {g.nodeCapacity(), g.edgeCapacity(), g.faceCapacity()}; }

    // Indexes every edge and face of `g`.
    void begin(const Graph& g);
    // One application added the ids in [from, to): keeps them (and indexes
    // them), or removes them if they intersect the graph. Returns whether
    // they were kept.
    bool admit(Graph& g, const Capacities& from, const Capacities& to);
    std::size_t cancelled() const { return cancelled_; }

private:
    struct Shape {
        std::vector<vec3> points;   // an edge's two ends, or a face's corners
        std::array<NodeId, 2> ends{kNoId, kNoId};
        double radius = 0;          // an edge's thickness (0 for a face, or an edge that bounds one)
    };
    Shape edgeShape(const Graph& g, EdgeId e) const;
    Shape faceShape(const Graph& g, FaceId f) const;
    Aabb boxOf(const Shape& s) const;
    bool crosses(const Graph& g, const Shape& s, bool isFace, std::uint32_t id, const Capacities& from) const;

    std::optional<SpatialBoxGrid> edges_, faces_;
    std::size_t cancelled_ = 0;
};

}  // namespace g2d::rt
