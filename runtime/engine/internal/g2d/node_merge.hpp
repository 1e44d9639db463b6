#pragma once
// G^3's merging of coinciding primitives (Laganeckiene 2012, §3.1): after a
// step of a rule that merges, every node the step created or moved that
// lies within the rule's tolerance of another node merges into it, and the
// degenerate situations this makes are repaired.
//
//   1. Two nodes coincide: the one with the lower id survives (the older;
//      among two new ones, the first made) at the midpoint of the two, with
//      the mean of their radii; the other's edges and face corners move to
//      it and it is removed. Candidates are taken in id order.
//   2. An edge between the two merged nodes is removed.
//   3. Two edges of one kind with the same ends (either direction) are one:
//      the older (lower id) stays.
//   4. A face left with fewer than 3 corners is removed.
//   5. A node twice in a row in a face is kept once; a node twice apart
//      splits the face at it into two faces (each kept if it has 3 or more
//      corners; the part holding the face's first corner keeps the face's
//      id, the other is a new face with a copy of its attributes).
//   6. A face whose sides fold back (a b … b a) is split the same way and
//      loses its two-cornered parts.
//   7. Two faces with the same corners (in any order) are one: the older stays.
//
// Nodes are found through a spatial hash grid kept up to date with every
// step's changes (spatial_grid.hpp), so a merge costs what the step changed.
#include <cstdint>
#include <functional>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/spatial_grid.hpp"

namespace g2d::rt {

// The tolerance of a rule's `merge` when the grammar sets none (`merge within`).
inline constexpr double kDefaultMergeTolerance = 1e-6;

class NodeMerger {
public:
    // Copies a face's attributes to a new face made by a split (the back
    // end's storage); the graph's own pools by default.
    using CopyFace = std::function<void(Graph& g, FaceId from, FaceId to)>;

    // Indexes every live node; `cellSize`: the grid's cell, a few tolerances.
    NodeMerger(const Graph& g, double cellSize, CopyFace copyFace);

    // Brings the index up to date with the nodes the last step changed
    // (Graph::changedNodes), before they are forgotten; the new and moved
    // ones are the step's merge candidates.
    void sync(const Graph& g);
    // Merges the last step's new and moved nodes (those sync() saw) within
    // `tolerance` of another node. Returns how many nodes merged away.
    std::size_t mergeChanged(Graph& g, double tolerance);

private:
    void index(NodeId n, vec3 p);
    void unindex(NodeId n);
    void merge(Graph& g, NodeId keep, NodeId gone);
    void mergeDuplicateEdges(Graph& g, NodeId n);
    void repairFace(Graph& g, FaceId f);
    void removeDuplicateFaces(Graph& g, NodeId n);

    SpatialGrid grid_;
    CopyFace copyFace_;
    std::vector<vec3> at_;              // by node id: where it is indexed
    std::vector<std::uint8_t> indexed_;
    std::vector<NodeId> candidates_;    // new or moved since the last merge
};

}  // namespace g2d::rt
