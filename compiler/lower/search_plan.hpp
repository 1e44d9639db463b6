#pragma once
// A rule's search plans (GrGen style: bind the most selective element first,
// then walk incidences, testing each condition as soon as every element it
// reads is bound), and what incremental matching needs to know of the
// pattern (rt::RuleInfo): computed here, from the IR, for both back ends.
#include <cstdint>
#include <vector>

#include "g2d/match_set.hpp"
#include "ir/ir.hpp"

namespace g2d::lower {

// One step of a search plan: bind one more pattern element, or test.
struct PlanStep {
    enum class Op {
        ScanNodes,    // node := each host node of its kind (or any node for a wildcard)
        ExtendEdge,   // edge := each edge incident to bound node `from`; node := its other end
        ConnectEdge,  // edge := each edge between two bound nodes
        BindFace,     // face := each face at bound node `from` (-1: of its kind), with its corners
        Check,        // evaluate conditions[condition]
    } op = Op::ScanNodes;
    int node = -1;
    int edge = -1;
    int face = -1;
    int from = -1;
    int fromCorner = -1;               // BindFace: the corner (of the face's pattern corners) `from` is
    bool fromIsSource = true;          // ExtendEdge: `from` is the edge's source
    int condition = -1;
};

// `nodes` and `edges` are numbered from nodeBase and edgeBase (a negative
// condition extends its rule's match: nodes below nodeBase and edges below
// edgeBase are already bound).
// `anchor` >= 0: that node is bound before the search starts.
// Faces (numbered from faceBase) are bound from a bound corner, or else
// scanned before any node: a face binds its corners.
std::vector<PlanStep> buildSearchPlan(const std::vector<ir::PatternNode>& nodes, const std::vector<ir::PatternEdge>& edges,
                                      const std::vector<ir::PatternFace>& faces, const std::vector<ir::Condition>& conditions,
                                      int nodeBase, int edgeBase, int boundOuterNodes, int anchor = -1, int faceBase = 0);
// A pattern face's node slots in cyclic order: its corners, or its hidden anchor.
std::vector<int> faceSlots(const ir::PatternFace& f);

// How far (in edges) from a changed node a match can be affected: 0 without
// negative conditions (a match reads only its own elements), else the depth
// of the deepest negative-condition element read; -1 when a negative
// condition has a part not connected to the match (any change may matter),
// unless it is a node near a point (near_negative.hpp).
int repairRadius(const ir::Rule& rule);
// Per match node: which changes among the host node's edges alone (an edge
// added or removed) can make or break a match binding it there. Every edge
// between two match nodes is read from one end only, so a hub's edge changes
// need not revisit every match binding the hub.
std::vector<rt::Incidence> incidenceReaders(const ir::Rule& rule);
// Per match node: which of its host's edge lists it reads (rt::RepairArea::kOut
// | kIn; 0 where `reads` is None). A node reading only the pattern's edges
// reads the directions of its pattern edges (an undirected one or a loop:
// both); one reading every edge, both. A host whose outgoing edges alone
// changed is then not searched again at a node reading only incoming ones,
// and vice versa: a path's split revisits the source's end only.
std::vector<std::uint8_t> incidenceDirections(const ir::Rule& rule, const std::vector<bool>& directed,
                                              const std::vector<rt::Incidence>& reads);
// Per match node: a search anchored there at a node the step created cannot
// add a match, so repair skips it. Such a match binds one of the node's
// edges, all new, and is added from the first of its pattern nodes whose
// host is searched: an earlier pattern node joined to this one by a pattern
// edge and reading incidences is (both ends of a new edge are marked).
std::vector<bool> newHostsAddingNothing(const ir::Rule& rule, const std::vector<rt::Incidence>& reads);
// Per match node: the distinct kinds of its pattern edges, all of which a
// host must have had (rt::Graph::edgeKindsAt) to be searched there; empty
// where that test cannot skip anything (no pattern edges, or a grammar of
// `edgeKinds` <= 1 edge kinds: every node with an edge has it).
std::vector<std::vector<int>> edgeKindsNeeded(const ir::Rule& rule, int edgeKinds);

}  // namespace g2d::lower
