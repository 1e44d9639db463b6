#pragma once
// A rule's searches as ordered lists of operations, decided once for both
// back ends: the interpreter walks them, the C++ emitter prints each as a
// loop or a test. Each operation carries every decision about it: the kinds
// to test, the earlier slots a host must differ from, the edge kinds a host
// node must have, the `ordered` comparisons from the sketch, and whether a
// search that keeps only matches binding a new edge tests that here.
// Slots are numbered as in ir::PlanStep: pattern nodes and edges first, a
// negative condition's own after them.
#include <cstdint>
#include <variant>
#include <vector>

#include "ir/ir.hpp"

namespace g2d::lower {

// `ordered`: the host of the node being bound must not lie past the host of
// `other` on `axis` (0: x, 1: y) in the direction the sketch forbids: when
// `before`, the node is drawn before `other` (smaller coordinate), so its host
// must not be greater; otherwise not smaller. Ties are allowed.
struct OrderCheck {
    int other;
    int axis;
    bool before;
};

// node := each host node of `kind` (-1: every live node, by id).
struct ScanNodes {
    int node;
    int kind;
    std::uint32_t edgeKinds;        // rt::Graph::edgeKindBit mask the host must have had (0: no test)
    std::vector<int> distinctNodes; // earlier node slots
    std::vector<OrderCheck> ordered;
};
// edge := each edge at bound node `from` (outgoing if fromIsSource, else
// incoming; both for an undirected kind); node := its other end.
struct ExtendEdge {
    int edge, from, node;
    int kind;                       // the edge's
    bool directed, fromIsSource;
    int nodeKind;                   // -1: any
    std::vector<int> distinctEdges, distinctNodes;
    std::vector<OrderCheck> ordered;
    bool newEdgeGate;               // binds the pattern's last edge (see RuleSet::findAnchored)
};
// edge := each edge between bound nodes `from` and `to` (either way for an undirected kind).
struct ConnectEdge {
    int edge, from, to;
    int kind;
    bool directed;
    std::vector<int> distinctEdges;
    bool newEdgeGate;
};
// face := each face at bound node `from` (-1: each face of `kind`, by id),
// with each of its rotations putting `from` at corner `fromCorner`: its
// corners, from that rotation's first on, go to `corners` in order, a slot
// bound before comparing, one bound here taking the host. Without
// `anyCount`, the face has exactly corners.size() corners and every
// rotation is a match; with it (`f: Kind`), `corners` is the face's hidden
// anchor and only the face's first corner is bound there.
// Scanned faces go by rotation, from the face's first corner on; faces at a
// node go by the node's corner list (newest first).
struct MatchFace {
    int face, kind;
    int from, fromCorner;
    std::vector<int> corners;
    bool anyCount;
    std::vector<std::uint8_t> cornerBound;   // per corner
    std::vector<int> cornerKinds;            // per corner bound here (-1: any)
    std::vector<int> distinctNodes;          // node slots bound before
    std::vector<int> distinctFaces;          // face slots bound before
};
// node := each host node of `kind` near a point (a negative condition's
// only node, near_negative.hpp): those within `radius` of `centre`, from the
// spatial index (rt::NearQueries::nodesNear), by id; the conditions that
// follow test the distance exactly. `near` numbers the rule's such negative
// conditions (rt::RuleInfo::nearKinds).
// With `join` (lower::nearJoin), the node of a pattern piece near bound
// ones: no disk is recorded (a match holds both ends, so repair finds it
// from either), and `kind` may be -1 (any node).
struct ScanNear {
    int node;
    int kind;
    int near;                       // the negative condition's index among the rule's near ones (-1 for a join)
    int key;                        // the node slot the disk is recorded under
    const ir::Expr* centre;
    const ir::Expr* radius;
    std::vector<int> distinctNodes; // earlier node slots
    bool join = false;
    std::uint32_t edgeKinds = 0;    // a join's: rt::Graph::edgeKindBit mask the host must have had (0: no test)
};
struct Filter {
    const ir::Expr* condition;
};
using MatchOp = std::variant<ScanNodes, ScanNear, ExtendEdge, ConnectEdge, MatchFace, Filter>;
using MatchList = std::vector<MatchOp>;

struct MatchProgram {
    MatchList full;                              // every match
    std::vector<MatchList> anchored;             // per pattern node: with it already bound
    std::vector<std::uint32_t> anchorEdgeKinds;  // per pattern node: what a host must have had to anchor it
    std::vector<MatchList> negatives;            // per negative condition: the outer slots already bound
    int nodeSlots = 1, edgeSlots = 1, faceSlots = 1;   // the most slots any list uses (at least 1)
};

MatchProgram lowerMatch(const ir::Program& prog, const ir::Rule& rule);

}  // namespace g2d::lower
