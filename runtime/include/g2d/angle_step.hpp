#pragma once
// `layout angles`: Merrell 2023's drawing step inside a derivation. A rule's
// application is prepared, then drawn before it is committed: the graph as
// the application would leave it becomes an AngleGraph (edges point along
// their kinds' angles), its new nodes free, and rt::drawAngleGraph looks for
// positions. A rejected proposal is discarded (the step changes nothing and
// still counts); an accepted one is committed and its positions set (new
// nodes, and old ones the drawing freed).
//
// What an application does to the graph is static per daughter
// (DaughterShape, decided by the compiler's lowering), so the derivation
// needs nothing from a back end but the prepared match.
#include <vector>

#include "g2d/angle_drawing.hpp"
#include "g2d/graph.hpp"
#include "g2d/match_set.hpp"

namespace g2d::rt {

// An edge kind's layout (`layout { angle = …; … }`); angle in radians.
struct EdgeGeometry {
    bool given = false;
    double angle = 0, minLength = 0, maxLength = 0;
    int left = -1, right = -1;     // face kinds traced on either side (-1: none)
};

struct AngleLayoutSpec {
    DrawingSettings settings;
    bool connected = false;            // `connected = true;`: no application may split what it touches (connected_guard.hpp)
    std::vector<EdgeGeometry> kinds;   // by kind index (nodes' and faces' unused)
};

// What applying one daughter does, in pattern terms.
struct DaughterShape {
    std::vector<int> deletedNodes;     // pattern node indices (their edges go too)
    std::vector<int> deletedEdges;     // pattern edge indices
    int newNodes = 0;                  // created in this order: ids newNodesFrom, newNodesFrom + 1, …
    struct NewEdge {
        int src = 0, dst = 0;          // >= 0: a pattern node; < 0: new node -1 - k
        int kind = -1;
    };
    std::vector<NewEdge> newEdges;
    std::vector<int> newNodeKinds;     // per new node, in creation order (the cost's counts)
};

class AngleStep {
public:
    // Draws the graph `shape` would make of `g` at `m`. Returns whether a
    // drawing was accepted; its positions wait for place().
    bool propose(const Graph& g, const DaughterShape& shape, Match m, const AngleLayoutSpec& spec, Rng& rng);
    // After the commit: the new nodes (ids from newNodesFrom) and freed old ones take their positions.
    void place(Graph& g, NodeId newNodesFrom) const;

    long long rejected() const { return rejected_; }

private:
    std::vector<int> index_;           // host node id -> vertex (-1: not in the drawing)
    std::vector<NodeId> host_;         // vertex -> host node id (kNoId: a new node)
    std::vector<char> deletedNode_, deletedEdge_;
    DrawingResult result_;
    int firstNew_ = 0;                 // vertices from here on are the new nodes
    long long rejected_ = 0;
};

}  // namespace g2d::rt
