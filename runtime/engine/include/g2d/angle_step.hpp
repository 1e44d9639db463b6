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
#include <memory>
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
    double unit = 0;               // > 0: lengths are whole multiples of it
    double bend = 0;               // > 0: drawn bent after the derivation, by up to this many radians a segment (edge_bends.hpp)
};

struct AngleLayoutSpec {
    DrawingSettings settings;
    bool connected = false;            // `connected = true;`: no application may split what it touches (connected_guard.hpp)
    std::vector<EdgeGeometry> kinds;   // by kind index (nodes' and faces' unused)
    double bendSegment = 0.1;          // bent edges are cut into segments about this long
    int bendSmooth = 5;                // … whose random turns are averaged over this many segments
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

// Draws each proposal. Without areas to keep consistent, only the part of
// the graph the change can move is built (the vertices within I - 1 edges of
// the change, and their edges: every vertex the step may free is among
// them), and the rest comes from a spatial index of the graph's edges kept
// up to date after each commit: a proposal then costs what its
// neighbourhood does, at any size of the graph, and is drawn exactly as the
// whole graph would draw it (same system, same draws, same tests).
class AngleStep {
public:
    // `whole`: always build the system from the whole graph (the reference
    // the part must equal; for tests).
    explicit AngleStep(bool whole = false) : whole_(whole) {}
    // Draws the graph `shape` would make of `g` at `m`. Returns whether a
    // drawing was accepted; its positions wait for place().
    bool propose(const Graph& g, const DaughterShape& shape, Match m, const AngleLayoutSpec& spec, Rng& rng);
    // After the commit: the new nodes (ids from newNodesFrom) and freed old
    // ones take their positions, and the index follows the step's changes
    // (g's change list, not yet forgotten).
    void place(Graph& g, NodeId newNodesFrom);

    long long rejected() const { return rejected_; }

private:
    class Index;
    void markDeleted(const Graph& g, const DaughterShape& shape, Match m);
    void unmarkDeleted();
    void addVertices(const Graph& g, const std::vector<NodeId>& fixed, const DaughterShape& shape, const AngleLayoutSpec& spec,
                     AngleGraph& ag);
    void buildWhole(const Graph& g, const DaughterShape& shape, Match m, const AngleLayoutSpec& spec, AngleGraph& ag);
    void buildPart(const Graph& g, const DaughterShape& shape, Match m, const AngleLayoutSpec& spec, AngleGraph& ag);
    AngleEdge edgeOf(const AngleLayoutSpec& spec, int kind, int from, int to) const;

    bool whole_;
    std::vector<int> index_;           // host node id -> vertex (-1: not in the drawing)
    std::vector<NodeId> host_;         // vertex -> host node id (kNoId: a new node)
    std::vector<char> deletedNode_, deletedEdge_, inPart_;   // by host id (inPart_: edges)
    std::vector<NodeId> goneNodes_;
    std::vector<EdgeId> goneEdges_, partEdges_;
    DrawingResult result_;
    int firstNew_ = 0;                 // vertices from here on are the new nodes
    long long rejected_ = 0;
    std::shared_ptr<Index> grid_;      // made at the first part drawn
};

}  // namespace g2d::rt
