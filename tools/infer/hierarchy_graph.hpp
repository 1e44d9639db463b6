#pragma once
// One graph of Merrell's graph hierarchy (§4.2–4.3): primitives glued at
// their half-edges. Every vertex is a primitive, so a vertex's edges are its
// primitive's half-edges by slot (counter-clockwise), each either glued to
// another vertex's slot or open. The open ones, walked counter-clockwise
// around the graph, are its boundary string; each carries its winding W, the
// walk's accumulated turning as it leaves along that half-edge, as the
// integer `wind` with W = direction + 360·wind. The turn symbols of the
// paper are the differences of consecutive winds (∧ +1, ∨ −1), and a
// boundary closes with one turn: the entry after the last is the first with
// wind + 1.
#include <string>
#include <vector>

#include "infer/labelled_example.hpp"

namespace g2d::infer {

struct BoundaryEntry {
    int half = 0;      // half-edge label
    int vertex = -1;   // the vertex it leaves from (-1: an edge graph's end)
    int slot = -1;     // its slot there
    int wind = 0;
};

struct Link {
    int vertex = -1, slot = -1;   // -1: open
};

struct HierarchyGraph {
    std::vector<int> type;                   // per vertex: its primitive
    std::vector<std::vector<Link>> links;    // per vertex, per slot
    std::vector<BoundaryEntry> boundary;     // empty: complete (the string ∧)
    int edgeLabel = -1;                      // >= 0: the edge graph a∧ā of this label (no vertices)
    int loops = 0;                           // loop glues made

    bool isEdgeGraph() const { return edgeLabel >= 0; }
    bool complete() const { return boundary.empty() && !isEdgeGraph(); }
    int vertexCount() const { return static_cast<int>(type.size()); }
    int gluedEdges() const;
    // Glue operations that made it, plus one (§4.3: primitives are generation 1, edge graphs 0).
    int generation() const { return isEdgeGraph() ? 0 : gluedEdges() + 1; }
};

HierarchyGraph primitiveGraph(const LabelledExample& ex, int primitive);
HierarchyGraph edgeGraph(const LabelledExample& ex, int edgeLabel);

// Branch glue (§4.2): boundary entry `entry` of g glued to slot `slot` of a
// new vertex of primitive `primitive`, whose half there is the complement.
HierarchyGraph branchGlue(const LabelledExample& ex, const HierarchyGraph& g, int entry, int primitive, int slot);
// Loop glue (§4.2) of boundary entries i and i + 1 (cyclically); false when
// they cannot be glued: not complementary, not turning 360° between them,
// one vertex, or two vertices already joined (straight edges would overlap).
bool loopGlue(const LabelledExample& ex, const HierarchyGraph& g, int i, HierarchyGraph& out);

// The boundary, walked from the structure (the first open slot starts it, at wind 0).
std::vector<BoundaryEntry> walkBoundary(const LabelledExample& ex, const HierarchyGraph& g);

// A key equal for two graphs exactly when they are the same graph (the
// stars fix the embedding, so a breadth-first numbering from the best start
// vertex is canonical).
std::string canonicalCode(const HierarchyGraph& g);

// Whether `pattern` occurs in `host` as a double-pushout match (§5, Fig 7):
// its vertices map one to one onto host vertices of the same primitive with
// its glued edges, and each of its open half-edges is open in the host or
// leads to a vertex outside the image (the interface, never one of the
// pattern's own vertices).
bool occursIn(const HierarchyGraph& pattern, const HierarchyGraph& host);
// The first such match (per pattern vertex, its host vertex), or empty.
// Patterns are connected (every hierarchy graph is).
std::vector<int> findOccurrence(const HierarchyGraph& pattern, const HierarchyGraph& host);

// The boundary as the paper writes it (a, ā, ∧, ∨), for messages and tests.
std::string boundaryString(const LabelledExample& ex, const std::vector<BoundaryEntry>& boundary);

}  // namespace g2d::infer
