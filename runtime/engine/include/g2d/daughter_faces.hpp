#pragma once
// A daughter's new faces and `insert`s, as both back ends make them, so that
// orientation and the --stats counters (Graph::FaceCounts) are decided in one
// place.
#include <span>

#include "g2d/graph.hpp"

namespace g2d::rt {

// Adds the face `corners` of `kind`. A face already on one of its sides that
// runs that side the same way makes it disagree with that neighbour
// (consistently oriented faces use a shared side in opposite directions).
// With `orient` (the kind is `oriented`), a face that disagrees with some
// neighbour and agrees with none is made reversed, its first corner kept:
// G^3's fix of Create face (Laganeckiene 2012, §2.4.5, Fig. 2.3). A face left
// disagreeing counts in FaceCounts::againstNeighbour.
FaceId addDaughterFace(Graph& g, int kind, std::span<const NodeId> corners, long long age, bool orient);

// `insert m between a and b` (Graph::insertBetween); one with no face on
// side a–b counts in FaceCounts::insertsWithoutSide.
void insertDaughterCorner(Graph& g, NodeId a, NodeId b, NodeId m);

}  // namespace g2d::rt
