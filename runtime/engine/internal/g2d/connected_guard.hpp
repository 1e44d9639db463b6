#pragma once
// `layout angles { connected = true; }` (Merrell 2023, Appendix A: a
// connected output): an application must not split what it touches. The
// nodes it touches — its kept match nodes, its new nodes, and the surviving
// ends of the edges it deletes — must be connected to each other in the
// graph it would leave, and it must not delete the last node. Checked before
// the commit on the graph as it is, with the change laid over it.
//
// The search goes out from every touched node at once (one breadth-first
// search, each vertex owned by the front that reached it first) and stops
// when the fronts have met (connected: usually within a few faces of the
// change) or when the fronts of one side have run out (a split: the
// smaller side has then been walked).
#include <vector>

#include "g2d/angle_step.hpp"
#include "g2d/graph.hpp"
#include "g2d/match_set.hpp"

namespace g2d::rt {

class ConnectedGuard {
public:
    // Whether applying `shape` at `m` keeps the touched nodes connected (and the graph not emptied).
    bool keepsConnected(const Graph& g, const DaughterShape& shape, Match m);

private:
    int rootOf(int front);
    std::vector<char> deletedNode_, deletedEdge_;
    std::vector<int> owner_;          // by vertex (host ids, then new nodes past them): the front that reached it, -1
    std::vector<int> parent_;         // fronts' union-find
    std::vector<int> touched_, queue_, visited_;
    std::vector<int> pending_;        // per set of fronts (its root): vertices queued, not yet visited
};

}  // namespace g2d::rt
