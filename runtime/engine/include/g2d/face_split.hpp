#pragma once
// G^3's Split face (Laganeckiene 2012, §2.4.5 and §3.4) on one face, given
// which of its corners meet the command's secondary conditions (the chosen
// corners, k of them):
//
//   k >= 3  a node (make.centre); an edge from each chosen corner to it; and
//           for each two chosen corners that follow each other round the
//           face, a face of the corners from the one to the next, then the
//           new node (all corners chosen: a fan). The face is replaced.
//           Without make.centre the face is left alone.
//   k == 2  no node (§3.4): an edge from the first chosen corner to the
//           second, and two faces, the corners from each chosen one round to
//           the other. The face is replaced — unless the two are neighbours
//           on it (a face needs three corners): then it is left alone.
//   k < 2   the face is left alone (one corner cannot divide it).
//
// The corners are the face's as they are now, from its first one; a corner
// is chosen when it is in `chosen` (the caller judged them before the step,
// so a corner the step inserted since is not chosen). New faces have the
// face's kind and run its way round, and get its attributes (make.copyFace)
// before it goes. The caller's makers give the new node and edges their
// attributes.
#include <functional>
#include <span>
#include <vector>

#include "g2d/graph.hpp"

namespace g2d::rt {

struct SplitMakers {
    std::function<NodeId()> centre;                           // empty: only a chord cuts
    std::function<EdgeId(NodeId from, NodeId to)> edge;
    std::function<void(FaceId from, FaceId to)> copyFace;
};

struct FaceSplit {
    NodeId centre = kNoId;          // kNoId: none made
    std::vector<EdgeId> edges;
    std::vector<FaceId> faces;      // empty: the face was left alone
};

FaceSplit splitFace(Graph& g, FaceId f, std::span<const NodeId> chosen, const SplitMakers& make, long long step);

}  // namespace g2d::rt
