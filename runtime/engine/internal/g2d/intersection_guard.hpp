#pragma once
// G^3's intersection tests (Laganeckiene 2012, §3.2; docs/language.md §16.8)
// for a rule with `intersect`. Each application runs under a graph journal
// (graph_journal.hpp); after it, what it made or changed — its new edges and
// faces, the edges and faces at the nodes it moved or gave a new radius,
// the edges it rewired, the faces it put a corner into — is tested against
// every edge and face of the graph (the step's earlier, kept applications
// included): an edge is a segment, thick by its end nodes' radii unless it
// bounds a face; a face is its triangulation (geometry3.hpp). An
// application that intersects anything is undone (Graph::endJournal), as
// if it had not been applied. Touching is not intersecting: elements that
// share a node or a side meet there, and the tests are open there.
//
// In the plane (a 2D grammar) a face is an area: an edge or face intersects
// it by crossing its outline, and what lies inside it is not tested against
// it (a background face, a room of a plan).
//
// Candidates come from a grid of boxes (spatial_grid.hpp) built when the
// step begins and grown with every element made or moved.
#include <array>
#include <optional>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/spatial_grid.hpp"

namespace g2d::rt {

class IntersectionGuard {
public:
    explicit IntersectionGuard(bool plane) : plane_(plane) {}
    // Indexes every edge and face of `g`.
    void begin(const Graph& g);
    // One application ran under `g`'s journal, which this ends: keeps what
    // it did (and indexes it), or undoes it if it intersects the graph.
    // Returns whether it was kept.
    bool admit(Graph& g);
    std::size_t cancelled() const { return cancelled_; }

private:
    struct Shape {
        std::vector<vec3> points;   // an edge's two ends, or a face's corners
        std::vector<NodeId> nodes;  // the same nodes
        double radius = 0;          // an edge's thickness (0 for a face, or an edge that bounds one)
    };
    Shape edgeShape(const Graph& g, EdgeId e) const;
    Shape faceShape(const Graph& g, FaceId f) const;
    Aabb boxOf(const Shape& s) const;
    // What the journalled application made or changed: edges, then faces.
    void changed(const Graph& g, const GraphJournal& j, std::vector<EdgeId>& edges, std::vector<FaceId>& faces) const;
    bool crosses(const Graph& g, const Shape& s, bool isFace, std::uint32_t id, const GraphJournal::Capacities& from) const;
    bool edgeMeetsFace(const Graph& g, const Shape& edge, FaceId f, const Shape& face) const;

    bool plane_;
    std::optional<SpatialBoxGrid> edges_, faces_;
    std::size_t cancelled_ = 0;
    std::vector<std::uint32_t> near_;
};

}  // namespace g2d::rt
