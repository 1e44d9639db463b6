#pragma once
// G^3's Split face (Laganeckiene 2012, §2.4.5 and §3.4) on one face, given
// which of its corners meet the command's secondary conditions (the chosen
// corners, k of them):
//
//   k >= 3  a node at `centre`; an edge from each chosen corner to it; and for
//           each two chosen corners that follow each other round the face, a
//           face of the corners from the one to the next, then the new node
//           (all corners chosen: a fan). The face is replaced.
//   k == 2  no node (§3.4): an edge from the first chosen corner to the
//           second, and two faces, the corners from each chosen one round to
//           the other. The face is replaced — unless the two are neighbours
//           on it (a face needs three corners): then it is left alone.
//   k < 2   the face is left alone (one corner cannot divide it).
//
// New faces have the face's kind and run its way round; `copyFace(f, new)`
// gives each the face's attributes before the face goes. The new node and
// edges are the caller's to give attributes (their kinds' defaults).
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "g2d/graph.hpp"

namespace g2d::rt {

struct FaceSplit {
    NodeId centre = kNoId;          // kNoId: none made
    std::vector<EdgeId> edges;
    std::vector<FaceId> faces;      // empty: the face was left alone
};

// `corners`: f's corners from its first one (as read before the step),
// `chosen[i]` whether corners[i] meets the conditions.
FaceSplit splitFace(Graph& g, FaceId f, std::span<const NodeId> corners, std::span<const std::uint8_t> chosen, vec3 centre,
                    int nodeKind, int edgeKind, long long step, const std::function<void(FaceId from, FaceId to)>& copyFace);

}  // namespace g2d::rt
