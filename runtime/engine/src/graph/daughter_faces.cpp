#include "g2d/daughter_faces.hpp"

#include <algorithm>
#include <vector>

namespace g2d::rt {

namespace {

// How many existing uses of the sides of `corners` run the same way (against)
// and the opposite way (along).
struct SideUses {
    int against = 0, along = 0;
};

SideUses sideUses(const Graph& g, std::span<const NodeId> corners) {
    SideUses uses;
    const std::size_t k = corners.size();
    for (std::size_t i = 0; i < k; ++i) {
        const NodeId u = corners[i], v = corners[(i + 1) % k];
        g.eachSideUse(u, v, [&](FaceId, bool forward) { ++(forward ? uses.against : uses.along); });
    }
    return uses;
}

}  // namespace

FaceId addDaughterFace(Graph& g, int kind, std::span<const NodeId> corners, long long age, bool orient) {
    const SideUses uses = sideUses(g, corners);
    if (uses.against == 0) return g.addFace(kind, corners, age);
    if (orient && uses.along == 0) {
        thread_local std::vector<NodeId> reversed;
        reversed.assign(corners.begin(), corners.end());
        std::reverse(reversed.begin() + 1, reversed.end());
        return g.addFace(kind, reversed, age);
    }
    ++g.faceCounts().againstNeighbour;
    return g.addFace(kind, corners, age);
}

void insertDaughterCorner(Graph& g, NodeId a, NodeId b, NodeId m) {
    if (g.sideFaceCount(a, b) == 0) ++g.faceCounts().insertsWithoutSide;
    g.insertBetween(a, b, m);
}

}  // namespace g2d::rt
