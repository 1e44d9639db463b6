#pragma once
// The host graph: nodes and edges with stable ids (never reused), kinds,
// positions, attributes, per-element style overrides and ages.
//
// Laid out for millions of elements: a node record is 48 bytes and an edge
// record 40. Each node heads two intrusive doubly linked lists (its outgoing
// and its incoming edges) threaded through the edge records, so adding or
// deleting an edge is O(1), even at a hub, and nothing is allocated per
// element.
// Per-kind node indexes make a search's first step O(1) per candidate.
// Attributes live in per-kind pools (an element's `slot` indexes its kind's
// pool); a compiled grammar keeps them in its own typed arrays instead and
// uses the slot for those. Style overrides are rare and live in a pooled
// store (style_store.hpp), by interned property.
//
// Faces are the third class (graph_faces.cpp): an ordered cycle of corners,
// each corner a record threaded through its face's cycle and its node's
// list of corners.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "g2d/elem_class.hpp"
#include "g2d/graph_journal.hpp"
#include "g2d/grow_array.hpp"
#include "g2d/prefetch.hpp"
#include "g2d/style_store.hpp"
#include "g2d/value.hpp"
#include "g2d/vec_math.hpp"

namespace g2d::rt {

using NodeId = std::uint32_t;
using EdgeId = std::uint32_t;
using FaceId = std::uint32_t;
using CornerId = std::uint32_t;
inline constexpr std::uint32_t kNoId = 0xffffffffu;
// Kinds are stored in 16 bits per element.
inline constexpr std::size_t kMaxKinds = 32767;

struct KindInfo {
    ElemClass cls = ElemClass::Node;
    bool directed = false;
};

// A style property by name, as drawing resolves it for the writers.
struct StyleOverride {
    std::string_view prop;   // a name that outlives the item (a literal, the program, the graph)
    Value value;
};

class Graph;
class ElementScope;

// The edges touching a node, each once (outgoing first, then incoming; a
// self-loop only among the outgoing), newest first within each list.
class IncidentRange {
public:
    class iterator {
    public:
        iterator(const Graph* g, NodeId n, EdgeId e, bool in) : g_(g), n_(n), e_(e), in_(in) { settle(); }
        EdgeId operator*() const { return e_; }
        iterator& operator++();
        bool operator!=(const iterator& o) const { return e_ != o.e_ || in_ != o.in_; }
        bool operator==(const iterator& o) const { return !(*this != o); }

    private:
        void settle();
        const Graph* g_;
        NodeId n_;
        EdgeId e_;
        bool in_;
    };
    IncidentRange(const Graph* g, NodeId n) : g_(g), n_(n) {}
    iterator begin() const;
    iterator end() const { return iterator(g_, n_, kNoId, true); }

private:
    const Graph* g_;
    NodeId n_;
};

// The live nodes in id order (ids of removed nodes are skipped).
class LiveNodes {
public:
    class iterator {
    public:
        iterator(const Graph* g, NodeId n) : g_(g), n_(n) { settle(); }
        NodeId operator*() const { return n_; }
        iterator& operator++() {
            ++n_;
            settle();
            return *this;
        }
        bool operator!=(const iterator& o) const { return n_ != o.n_; }
        bool operator==(const iterator& o) const { return n_ == o.n_; }

    private:
        inline void settle();
        const Graph* g_;
        NodeId n_;
    };
    explicit LiveNodes(const Graph* g) : g_(g) {}
    iterator begin() const { return iterator(g_, 0); }
    inline iterator end() const;

private:
    const Graph* g_;
};

class Graph {
public:
    // `styleProps`: the program's style properties, numbered in this order
    // (ir::Program::styleProps), so that its code can set them by number.
    explicit Graph(std::vector<KindInfo> kinds, std::vector<std::string> styleProps = {});

    // Attributes a new element of `kind` starts with when none are given
    // (the interpreter's defaults; compiled grammars keep none here).
    void setKindDefaults(int kind, std::vector<Value> defaults);

    // The hot ones are defined inline below (they run several times a step).
    inline NodeId addNode(int kind, vec2 pos, long long age);
    NodeId addNode(int kind, vec2 pos, long long age, std::vector<Value> attrs);
    inline EdgeId addEdge(int kind, NodeId src, NodeId dst, long long age);
    EdgeId addEdge(int kind, NodeId src, NodeId dst, long long age, std::vector<Value> attrs);
    inline void removeEdge(EdgeId e);
    void removeNode(NodeId n);                  // with its incident (dangling) edges
    void reconnectEdge(EdgeId e, NodeId src, NodeId dst);

    bool nodeAlive(NodeId n) const { return n < nodes_.size() && nodes_[n].alive; }
    // Asks the processor to load an element's record now, so that the loads
    // of a match's scattered records overlap instead of waiting in turn.
    // (Half the records straddle two cache lines: 48 and 40 bytes.)
    void prefetchNode(NodeId n) const { prefetchRecordLines(&nodes_[n], sizeof(NodeRec)); }
    void prefetchEdge(EdgeId e) const { prefetchRecordLines(&edges_[e], sizeof(EdgeRec)); }
    bool edgeAlive(EdgeId e) const { return e < edges_.size() && edges_[e].alive; }
    std::size_t nodeCount() const { return liveNodes_; }
    std::size_t edgeCount() const { return liveEdges_; }
    std::size_t nodeCapacity() const { return nodes_.size(); }  // ids are below this
    std::size_t edgeCapacity() const { return edges_.size(); }

    int nodeKind(NodeId n) const { return nodes_[n].kind; }
    vec2 pos(NodeId n) const { return nodes_[n].pos; }
    void setPos(NodeId n, vec2 p) {
        if (journal_) [[unlikely]] journalNode(n);
        nodes_[n].pos = p;
        touchNode(n);
        if (faceCountAt(n) != 0) touchFacesAt(n);   // their geometry moved
    }
    // The third coordinate (grammars in 3D space): kept in a column of its
    // own, filled only once some node is given a z, so 2D graphs carry none.
    double z(NodeId n) const { return n < z_.size() ? z_[n] : 0.0; }
    vec3 pos3(NodeId n) const { return {nodes_[n].pos.x, nodes_[n].pos.y, z(n)}; }
    NodeId addNode(int kind, vec3 pos, long long age) {
        const NodeId n = addNode(kind, vec2(pos.x, pos.y), age);
        setZ(n, pos.z);
        return n;
    }
    void setPos(NodeId n, vec3 p) {
        setZ(n, p.z);
        setPos(n, vec2(p.x, p.y));
    }
    void setZ(NodeId n, double z) {
        if (journal_) [[unlikely]] journalNode(n);
        setColumn(z_, n, z);
    }
    // G^3's node radius (3D grammars), in a column of its own like z.
    double radius(NodeId n) const { return n < radius_.size() ? radius_[n] : 0.0; }
    void setRadius(NodeId n, double r) {
        if (journal_) [[unlikely]] journalNode(n);
        setColumn(radius_, n, r);
        touchNode(n);   // rules read it as a fact, as they read pos
    }
    long long nodeAge(NodeId n) const { return nodes_[n].age; }
    // The thesis tool's `.generation` (generations.hpp sets it when a
    // grammar reads it): 0 for the axiom's elements, and wherever unset.
    long long nodeGeneration(NodeId n) const { return n < nodeGen_.size() ? nodeGen_[n] : 0; }
    long long edgeGeneration(EdgeId e) const { return e < edgeGen_.size() ? edgeGen_[e] : 0; }
    long long faceGeneration(FaceId f) const { return f < faceGen_.size() ? faceGen_[f] : 0; }
    // Every element with an id from these on gets generation `generation`
    // (what one application created: ids are never reused).
    void setGenerationsFrom(NodeId nodesFrom, EdgeId edgesFrom, FaceId facesFrom, long long generation);
    void setFaceGeneration(FaceId f, long long generation);
    const Value& nodeAttr(NodeId n, int i) const { return pool_[nodes_[n].kind][attrIndex(nodes_[n].kind, nodes_[n].slot, i)]; }
    void setNodeAttr(NodeId n, int i, Value v);
    // The same without recording a change (a new node's, or a kept node's
    // whose change the caller records with touchNodeValues).
    void initNodeAttr(NodeId n, int i, Value v);
    // Valid until the next style is set on any element (the lists are pooled).
    StyleList nodeStyle(NodeId n) const;
    // A back end's own handle for the element's attributes (compiled grammars
    // keep them in typed arrays); kNoId until set.
    std::uint32_t nodeSlot(NodeId n) const { return nodes_[n].slot; }
    void setNodeSlot(NodeId n, std::uint32_t slot) { nodes_[n].slot = slot; }
    void setNodeStyle(NodeId n, StyleProp prop, Value&& v);
    // A copy of `v` (generated code keeps a literal style value as one constant).
    void setNodeStyle(NodeId n, StyleProp prop, const Value& v);
    void setNodeStyle(NodeId n, std::string_view prop, Value v) { setNodeStyle(n, styleProp(prop), std::move(v)); }

    int edgeKind(EdgeId e) const { return edges_[e].kind; }
    NodeId source(EdgeId e) const { return edges_[e].src; }
    NodeId target(EdgeId e) const { return edges_[e].dst; }
    long long edgeAge(EdgeId e) const { return edges_[e].age; }
    const Value& edgeAttr(EdgeId e, int i) const { return pool_[edges_[e].kind][attrIndex(edges_[e].kind, edges_[e].slot, i)]; }
    void setEdgeAttr(EdgeId e, int i, Value v);
    // The same for an edge added in this step: incremental matching tells a
    // new edge by its id (the step's new edges have the highest), so its ends
    // need no further mark.
    void initEdgeAttr(EdgeId e, int i, Value v);
    StyleList edgeStyle(EdgeId e) const;
    std::uint32_t edgeSlot(EdgeId e) const { return edges_[e].slot; }
    void setEdgeSlot(EdgeId e, std::uint32_t slot) { edges_[e].slot = slot; }
    void setEdgeStyle(EdgeId e, StyleProp prop, Value&& v);
    void setEdgeStyle(EdgeId e, StyleProp prop, const Value& v);
    void setEdgeStyle(EdgeId e, std::string_view prop, Value v) { setEdgeStyle(e, styleProp(prop), std::move(v)); }

    // ---- faces (runtime/src/graph_faces.cpp) ----
    // A face is an ordered cycle of at least 3 distinct live nodes, its
    // corners; its sides are the pairs of consecutive corners (the last and
    // the first included). Faces reference nodes, not edges: a side needs no
    // edge, and removing an edge leaves faces alone. Removing a node removes
    // the faces it is a corner of. Ids are never reused.
    // Throws OpError unless the corners are >= 3, distinct and live.
    FaceId addFace(int kind, std::span<const NodeId> corners, long long age);
    void removeFace(FaceId f);
    // Puts node m into every face with side {a, b} (either way round),
    // between a and b: G^3's Split edge. A face that has m as a corner
    // already is left alone. Returns how many faces grew.
    int insertBetween(NodeId a, NodeId b, NodeId m);
    // Corner surgery for merging nodes (node_merge.cpp): a new corner of
    // node m after corner c; corner c taken out of its face (which keeps
    // at least one corner: the caller removes faces that fall below 3);
    // corner c moved to node n.
    CornerId insertCornerAfter(CornerId c, NodeId m);
    // Records that f's corners changed (its facts, its anchor's matches, and
    // the faces around it, for `neighbours` and `touching`).
    void faceReshaped(FaceId f);
    void removeCorner(CornerId c);
    void moveCorner(CornerId c, NodeId n);
    // What daughters' faces and `insert`s did that a grammar seldom means
    // (daughter_faces.hpp): new faces left running a shared side the same
    // way as a face already on it, and inserts that found no face with their
    // side. Read by --stats (DerivationResult).
    struct FaceCounts {
        long long againstNeighbour = 0;
        long long insertsWithoutSide = 0;
    };
    FaceCounts& faceCounts() { return faceCounts_; }
    const FaceCounts& faceCounts() const { return faceCounts_; }

    // A face's holes: rings of nodes inside it, clockwise, that it does not
    // cover (an island of the drawing). Only `layout angles`' drawn faces
    // have them, set after the derivation, for the writers; a face's facts
    // (area, centroid, ...) are its outer ring's. Removing the face drops
    // them, and removing a node drops the rings it is on.
    void setFaceHoles(FaceId f, std::vector<std::vector<NodeId>> rings);
    std::span<const std::vector<NodeId>> faceHoles(FaceId f) const {
        return f < faceHoles_.size() ? std::span<const std::vector<NodeId>>(faceHoles_[f]) : std::span<const std::vector<NodeId>>();
    }
    // An edge's bend (Merrell's Appendix B, edge_bends.hpp): the points
    // between its source and its target, in that order. Only `layout
    // angles`' bending sets them, after the derivation, for the writers;
    // removing the edge drops them.
    void setEdgeBend(EdgeId e, std::vector<vec2> points);
    std::span<const vec2> edgeBend(EdgeId e) const {
        return e < edgeBends_.size() ? std::span<const vec2>(edgeBends_[e]) : std::span<const vec2>();
    }
    bool hasBends() const { return !edgeBends_.empty(); }
    bool faceAlive(FaceId f) const { return f < faces_.size() && faces_[f].alive; }
    std::size_t faceCount() const { return liveFaces_; }
    std::size_t faceCapacity() const { return faces_.size(); }   // ids are below this
    int faceKind(FaceId f) const { return faces_[f].kind; }
    long long faceAge(FaceId f) const { return faces_[f].age; }
    int cornerCount(FaceId f) const { return static_cast<int>(faces_[f].cornerCount); }
    // A face's corners in cyclic order: from firstCorner, nextCorner until
    // it comes back. A corner's side runs from its node to the next one's.
    CornerId firstCorner(FaceId f) const { return faces_[f].firstCorner; }
    CornerId nextCorner(CornerId c) const { return corners_[c].next; }
    CornerId prevCorner(CornerId c) const { return corners_[c].prev; }
    NodeId cornerNode(CornerId c) const { return corners_[c].node; }
    FaceId cornerFace(CornerId c) const { return corners_[c].face; }
    // The corners at a node, one per face it bounds (newest first): from
    // firstCornerAt, nextCornerAt until kNoId.
    CornerId firstCornerAt(NodeId n) const { return n < nodeCorners_.size() ? nodeCorners_[n].first : kNoId; }
    CornerId nextCornerAt(CornerId c) const { return corners_[c].nextAtNode; }
    int faceCountAt(NodeId n) const { return n < nodeCorners_.size() ? static_cast<int>(nodeCorners_[n].count) : 0; }
    std::span<const FaceId> facesOfKind(int kind) const { return {kindNodes_[kind].data(), kindNodes_[kind].size()}; }
    // Calls each(face, forward) for every face with side {u, v}, where
    // `forward` says the face runs from u to v. Scans the end with fewer faces.
    template <class Each>
    void eachSideUse(NodeId u, NodeId v, Each&& each) const;
    int sideFaceCount(NodeId u, NodeId v) const;
    // The distinct faces sharing a side with f, in the order of f's sides.
    void neighbours(FaceId f, std::vector<FaceId>& out) const;
    int neighbourCount(FaceId f) const;
    // The distinct faces sharing at least a corner with f (G^3's neighbouring
    // faces, Fig. 3.11: eight around a face of a quad grid).
    int touchingCount(FaceId f) const;
    // G^3's compound scopes (element_scope.hpp): while one is set, the
    // topological facts (element_facts.hpp) count only its elements.
    void setScope(const ElementScope* s) { scope_ = s; }
    const ElementScope* scope() const { return scope_; }
    // Geometry of the corners' positions: the signed area (shoelace;
    // positive when they run counter-clockwise, y up), its absolute value,
    // the perimeter, and the centroid as the mean of the corners (as G^3).
    double signedArea(FaceId f) const;
    double area(FaceId f) const;
    double perimeter(FaceId f) const;
    vec2 centroid(FaceId f) const;
    // The same in 3D; the vector area is half the sum of the corners' cross
    // products: its length is the area of a plane face, its direction the
    // normal seen from which the corners run counter-clockwise.
    double perimeter3(FaceId f) const;
    double area3(FaceId f) const;   // G^3 §3.4: the sum of the triangles of its §3.2.4 triangulation
    vec3 centroid3(FaceId f) const;
    vec3 vectorArea(FaceId f) const;
    // The least and greatest coordinates of an edge's ends (edge) or a face's corners.
    struct Bounds3 {
        vec3 lo, hi;
    };
    Bounds3 bounds3(bool edge, std::uint32_t id) const;
    const Value& faceAttr(FaceId f, int i) const { return pool_[faces_[f].kind][attrIndex(faces_[f].kind, faces_[f].slot, i)]; }
    void setFaceAttr(FaceId f, int i, Value v);
    void initFaceAttr(FaceId f, int i, Value v);   // without recording a change
    // Face `to` (of f's kind) takes f's attributes from the graph's own pool
    // (a back end with its own storage copies them there).
    void copyFaceAttrs(FaceId from, FaceId to);
    std::uint32_t faceSlot(FaceId f) const { return faces_[f].slot; }
    void setFaceSlot(FaceId f, std::uint32_t slot) { faces_[f].slot = slot; }
    StyleList faceStyle(FaceId f) const;
    void setFaceStyle(FaceId f, StyleProp prop, Value&& v);
    void setFaceStyle(FaceId f, StyleProp prop, const Value& v);
    // Faces created, removed or changed (attributes) since forgetChanges(),
    // each once; new ones have ids from the step's first new id on.
    void touchFace(FaceId f);
    // A match binding a face binds the face's first corner too, so changes
    // to a face are marked there for incremental matching: touchFace and a
    // moved corner mark it (values only for an attribute write), and adding
    // or removing a face marks its corners and its neighbours' first corners
    // (their `neighbours` changed).
    NodeId anchorOf(FaceId f) const { return cornerNode(firstCorner(f)); }
    // Whether adding or removing a face marks its neighbours' anchors (some
    // rule reads `neighbours`; the derivation sets it; on by default).
    void trackNeighbours(bool on) { trackNeighbours_ = on; }
    void touchFaceValues(FaceId f) {
        touchFace(f);
        touchNodeValues(anchorOf(f));
    }
    void touchFacesAt(NodeId n);
    std::span<const FaceId> changedFaces() const { return {dirtyFaces_.data(), dirtyFaces_.size()}; }

    // Any element by class: its kind, its back end's attribute handle, an attribute.
    int kindOf(ElemClass cls, std::uint32_t id) const {
        return cls == ElemClass::Edge ? edgeKind(id) : cls == ElemClass::Face ? faceKind(id) : nodeKind(id);
    }
    std::uint32_t slotOf(ElemClass cls, std::uint32_t id) const {
        return cls == ElemClass::Edge ? edgeSlot(id) : cls == ElemClass::Face ? faceSlot(id) : nodeSlot(id);
    }
    const Value& attrOf(ElemClass cls, std::uint32_t id, int i) const {
        return cls == ElemClass::Edge ? edgeAttr(id, i) : cls == ElemClass::Face ? faceAttr(id, i) : nodeAttr(id, i);
    }

    // Style property numbers (a new name is numbered after the others).
    StyleProp styleProp(std::string_view name) { return styles_.prop(name); }
    const std::string& stylePropName(StyleProp p) const { return styles_.name(p); }
    std::vector<std::string> styleProps() const { return styles_.names(); }

    // Live nodes of one kind (deterministic order), or of every kind (by id).
    std::span<const NodeId> nodesOfKind(int kind) const { return {kindNodes_[kind].data(), kindNodes_[kind].size()}; }
    LiveNodes allNodes() const { return LiveNodes(this); }

    // A superset of the kinds of the edges a node has (or had), one bit per
    // kind modulo 32: a search anchored at the node skips it at once when a
    // pattern node needs an edge kind it never had (the bit is set when an
    // edge is linked there and not cleared when it goes).
    static constexpr std::uint32_t edgeKindBit(int kind) { return std::uint32_t{1} << (static_cast<unsigned>(kind) & 31u); }
    std::uint32_t edgeKindsAt(NodeId n) const { return nodes_[n].edgeKinds; }

    // Incidence, as intrusive lists (newest first):
    //   for (EdgeId e = g.firstOut(n); e != kNoId; e = g.nextOut(e)) ...
    EdgeId firstOut(NodeId n) const { return nodes_[n].firstOut; }
    EdgeId nextOut(EdgeId e) const { return edges_[e].nextOut; }
    EdgeId firstIn(NodeId n) const { return nodes_[n].firstIn; }
    EdgeId nextIn(EdgeId e) const { return edges_[e].nextIn; }
    IncidentRange incident(NodeId n) const { return IncidentRange(this, n); }
    int degree(NodeId n) const;                 // a self-loop counts once
    int inDegree(NodeId n) const;
    int outDegree(NodeId n) const;

    const std::vector<KindInfo>& kinds() const { return kinds_; }

    // Change tracking for incremental matching, since the last
    // forgetChanges(): nodes created, deleted or changed themselves
    // (position, attributes), and nodes only whose incident edges were added
    // or removed, with which of their edge lists (outgoing, incoming)
    // changed. An edge whose attributes or ends change makes its ends count
    // as changed themselves (incremental matching tells an edge the step
    // added by its id, but keeps no other mark per edge).
    void touchNode(NodeId n) { touch(n, kChangedItself); }
    // Only attributes of `n` were written (a rule reading none of them need
    // not revisit it).
    void touchNodeValues(NodeId n) {
        touch(n, kChangedValues);
        valuesWritten_ = true;
    }
    void touchEdge(EdgeId e) { touch(edges_[e].src, kChangedOut); touch(edges_[e].dst, kChangedIn); }
    void touchEdgeItself(EdgeId e) { touchNode(edges_[e].src); touchNode(edges_[e].dst); }
    // The changed nodes (each once, in the order they first changed); for
    // each, whether it changed itself, or else which of its edge lists did
    // (RepairArea::kOut | kIn). Read in place by incremental matching: a
    // step's few changes are not copied out.
    std::span<const NodeId> changedNodes() const { return {dirty_.data(), dirty_.size()}; }
    bool changedItself(NodeId n) const { return (nodes_[n].marks & kChangedItself) != 0; }
    // The same, counting a node whose attributes alone were written as
    // changed itself when `values`.
    bool changedItself(NodeId n, bool values) const {
        return (nodes_[n].marks & (values ? kChangedItself | kChangedValues : kChangedItself)) != 0;
    }
    // Whether some node's attributes were written (touchNodeValues).
    bool valuesWritten() const { return valuesWritten_; }
    std::uint8_t changedLists(NodeId n) const {
        return static_cast<std::uint8_t>((nodes_[n].marks & (kChangedOut | kChangedIn)) >> 1);
    }
    std::size_t changedNodeCount() const { return dirty_.size(); }
    void forgetChanges();

    // An application that may be undone (graph_journal.hpp,
    // graph_journal.cpp): from beginJournal on, changes to older elements
    // are recorded in `j`; endJournal(true) undoes them and removes the new
    // elements, restoring the graph as it was (change marks aside: what was
    // undone counts as changed), endJournal(false) keeps them.
    void beginJournal(GraphJournal& j);
    void endJournal(bool undo);
    const GraphJournal* journal() const { return journal_; }

    // Bytes held by the graph's own arrays (for the benchmarks).
    std::size_t memoryBytes() const;

private:
    const ElementScope* scope_ = nullptr;
    GraphJournal* journal_ = nullptr;
    GraphJournal::Capacities capacities() const { return {nodes_.size(), edges_.size(), faces_.size()}; }
    void journalNode(NodeId n);
    void journalEdge(EdgeId e);
    void removeNewSince(const GraphJournal::Capacities& at);
    void revert(const GraphJournal::Entry& entry);
    void reviveFace(FaceId f);
    struct NodeRec {                         // 48 bytes
        vec2 pos{0, 0};
        long long age = 0;
        std::int16_t kind = -1;
        bool alive = true;
        // kChanged* bits (kept here: one cache line per node), and kStyled.
        // A byte, not bit fields: a record is then written without reading
        // it back (a bit field's store is a read-modify-write).
        std::uint8_t marks = 0;
        std::uint32_t slot = kNoId;
        std::uint32_t slotInKind = 0;            // its place in kindNodes_[kind]
        std::uint32_t edgeKinds = 0;             // edgeKindsAt
        EdgeId firstOut = kNoId, firstIn = kNoId;
    };
    struct EdgeRec {                         // 40 bytes
        long long age = 0;
        std::int16_t kind = -1;
        bool alive = true;
        bool styled = false;
        std::uint32_t slot = kNoId;
        NodeId src = kNoId, dst = kNoId;
        EdgeId nextOut = kNoId, nextIn = kNoId;
        EdgeId prevOut = kNoId, prevIn = kNoId;
    };
    struct FaceRec {                         // 32 bytes
        long long age = 0;
        std::int16_t kind = -1;
        bool alive = true;
        std::uint8_t marks = 0;                  // kFaceChanged, kStyled
        std::uint32_t slot = kNoId;
        std::uint32_t slotInKind = 0;            // its place in kindNodes_[kind]
        CornerId firstCorner = kNoId;
        std::uint32_t cornerCount = 0;
        std::uint32_t unused = 0;
    };
    struct CornerRec {                       // 24 bytes
        NodeId node = kNoId;
        FaceId face = kNoId;
        CornerId next = kNoId, prev = kNoId;              // in the face's cycle
        CornerId nextAtNode = kNoId, prevAtNode = kNoId;  // in the node's list
    };
    struct NodeCorners {                     // per node, from its first face on
        CornerId first = kNoId;
        std::uint32_t count = 0;
    };
    static_assert(sizeof(NodeRec) == 48 && sizeof(EdgeRec) == 40 && sizeof(FaceRec) == 32 && sizeof(CornerRec) == 24);
    static constexpr std::uint8_t kFaceChanged = 1;

    // Out and In as RepairArea::kOut and kIn, one bit up.
    static constexpr std::uint8_t kChangedItself = 1, kChangedOut = 2, kChangedIn = 4, kChangedValues = 16;
    static constexpr std::uint8_t kChanged = kChangedItself | kChangedOut | kChangedIn | kChangedValues, kStyled = 8;
    void touch(NodeId n, std::uint8_t what) {
        if (!(nodes_[n].marks & kChanged)) dirty_.push_back(n);
        nodes_[n].marks |= what;
    }
    std::size_t attrIndex(int kind, std::uint32_t slot, int i) const {
        return static_cast<std::size_t>(slot) * defaults_[kind].size() + static_cast<std::size_t>(i);
    }
    std::uint32_t newAttrBlock(int kind, std::vector<Value>* attrs);
    bool valuesWritten_ = false;
    bool trackNeighbours_ = true;
    void clearAttrBlock(int kind, std::uint32_t slot);
    inline void link(EdgeId e);
    inline void unlink(EdgeId e);
    void dropEdgeExtras(EdgeRec& rec, EdgeId e);   // attributes and styles of a removed edge
    void removeFacesAt(NodeId n);
    void touchNeighbourAnchors(FaceId f);
    template <class At>
    double sidesLength(FaceId f, At at) const;
    template <class At>
    auto cornerMean(FaceId f, At at) const;
    void unlinkAtNode(CornerId c);
    // A removed node's or face's record: out of its kind's index (swap-remove,
    // fixing the moved element's place), dead, its attributes and styles dropped.
    template <class Rec>
    void retire(Rec& rec, GrowArray<Rec>& recs, GrowArray<std::uint32_t>& styleLists, std::uint32_t id);
    // Its first part: out of its kind's index (swap-remove) and dead.
    template <class Rec>
    void unindex(Rec& rec, GrowArray<Rec>& recs);
    NodeCorners& cornersAt(NodeId n);
    [[noreturn]] static void deadEndpoint();

    std::vector<KindInfo> kinds_;
    std::vector<std::vector<Value>> defaults_;   // per kind
    // Whether any kind keeps its attributes in pool_ (never, for compiled
    // grammars: their typed arrays hold them), so that adding and removing
    // elements need not look up their kind's defaults.
    bool anyPooled_ = false;
    bool pooled(int kind) const { return anyPooled_ && !defaults_[kind].empty(); }
    std::vector<std::vector<Value>> pool_;       // per kind: blocks of defaults_[kind].size()
    // The columns that grow with the graph never copy themselves (grow_array.hpp).
    GrowArray<NodeRec> nodes_;
    std::vector<double> z_, radius_;         // by node id; empty until some node has a nonzero one
    std::vector<long long> nodeGen_, edgeGen_, faceGen_;   // by id; empty until some element has a nonzero one
    void setColumn(std::vector<double>& column, NodeId n, double v) {
        if (n >= column.size()) {
            if (v == 0.0) return;
            column.resize(nodes_.size(), 0.0);
        }
        column[n] = v;
    }
    GrowArray<EdgeRec> edges_;
    std::vector<GrowArray<NodeId>> kindNodes_;   // per node kind its nodes, per face kind its faces
    // Style overrides: each element's chain in styles_ (StyleStore::kNone
    // for none; sized when the first element of its class gets one).
    StyleStore styles_;
    GrowArray<std::uint32_t> nodeStyleList_, edgeStyleList_, faceStyleList_;
    static std::uint32_t& styleHead(GrowArray<std::uint32_t>& lists, std::uint32_t id, std::size_t capacity);
    std::size_t liveNodes_ = 0, liveEdges_ = 0, liveFaces_ = 0;
    std::vector<NodeId> dirty_;
    GrowArray<FaceRec> faces_;
    GrowArray<CornerRec> corners_;
    GrowArray<NodeCorners> nodeCorners_;
    std::vector<FaceId> dirtyFaces_;
    FaceCounts faceCounts_;
    std::vector<std::vector<std::vector<NodeId>>> faceHoles_;   // by face id; empty until a face has holes
    std::vector<std::vector<vec2>> edgeBends_;                   // by edge id; empty until an edge is bent
};

template <class Rec>
void Graph::unindex(Rec& rec, GrowArray<Rec>& recs) {
    auto& kindList = kindNodes_[rec.kind];
    const std::uint32_t moved = kindList.back();
    kindList[rec.slotInKind] = moved;
    recs[moved].slotInKind = rec.slotInKind;
    kindList.pop_back();
    rec.alive = false;
}

template <class Rec>
void Graph::retire(Rec& rec, GrowArray<Rec>& recs, GrowArray<std::uint32_t>& styleLists, std::uint32_t id) {
    unindex(rec, recs);
    clearAttrBlock(rec.kind, rec.slot);
    if (rec.marks & kStyled) styles_.drop(styleLists[id]);
    rec.marks &= static_cast<std::uint8_t>(~kStyled);
}

template <class Each>
void Graph::eachSideUse(NodeId u, NodeId v, Each&& each) const {
    // From the end with fewer faces: a fan's hub is not scanned for its rim.
    const bool fromU = faceCountAt(u) <= faceCountAt(v);
    const NodeId a = fromU ? u : v, b = fromU ? v : u;
    for (CornerId c = firstCornerAt(a); c != kNoId; c = nextCornerAt(c)) {
        if (cornerNode(nextCorner(c)) == b) each(cornerFace(c), fromU);        // runs a -> b
        else if (cornerNode(prevCorner(c)) == b) each(cornerFace(c), !fromU);  // runs b -> a
    }
}

NodeId Graph::addNode(int kind, vec2 pos, long long age) {
    const auto id = static_cast<NodeId>(nodes_.size());
    const std::uint32_t slot = pooled(kind) ? newAttrBlock(kind, nullptr) : kNoId;
    auto& ofKind = kindNodes_[kind];
    // Built in place: a record built aside and copied in is read back with
    // wide loads over its narrow stores, which cannot be forwarded (a stall).
    ::new (static_cast<void*>(nodes_.extendUnset(1)))
        NodeRec{pos, age, static_cast<std::int16_t>(kind), true, kChangedItself, slot,
                static_cast<std::uint32_t>(ofKind.size()), 0, kNoId, kNoId};
    ofKind.push_back(id);
    dirty_.push_back(id);
    ++liveNodes_;
    return id;
}

EdgeId Graph::addEdge(int kind, NodeId src, NodeId dst, long long age) {
    if (!nodeAlive(src) || !nodeAlive(dst)) deadEndpoint();
    const auto id = static_cast<EdgeId>(edges_.size());
    const std::uint32_t slot = pooled(kind) ? newAttrBlock(kind, nullptr) : kNoId;
    ::new (static_cast<void*>(edges_.extendUnset(1)))   // in place, as in addNode
        EdgeRec{age, static_cast<std::int16_t>(kind), true, false, slot, src, dst, kNoId, kNoId, kNoId, kNoId};
    link(id);
    ++liveEdges_;
    touchEdge(id);
    return id;
}

void Graph::link(EdgeId e) {
    // The ends and kind as locals: stores through the records could alias
    // them, and the compiler would read them again after each.
    auto& rec = edges_[e];
    const NodeId src = rec.src, dst = rec.dst;
    const std::uint32_t bit = edgeKindBit(rec.kind);
    NodeRec& s = nodes_[src];
    NodeRec& d = nodes_[dst];
    s.edgeKinds |= bit;
    d.edgeKinds |= bit;
    const EdgeId nextOut = s.firstOut;
    rec.prevOut = kNoId;
    rec.nextOut = nextOut;
    if (nextOut != kNoId) edges_[nextOut].prevOut = e;
    s.firstOut = e;
    const EdgeId nextIn = d.firstIn;
    rec.prevIn = kNoId;
    rec.nextIn = nextIn;
    if (nextIn != kNoId) edges_[nextIn].prevIn = e;
    d.firstIn = e;
}

void Graph::unlink(EdgeId e) {
    const auto& rec = edges_[e];
    (rec.prevOut != kNoId ? edges_[rec.prevOut].nextOut : nodes_[rec.src].firstOut) = rec.nextOut;
    if (rec.nextOut != kNoId) edges_[rec.nextOut].prevOut = rec.prevOut;
    (rec.prevIn != kNoId ? edges_[rec.prevIn].nextIn : nodes_[rec.dst].firstIn) = rec.nextIn;
    if (rec.nextIn != kNoId) edges_[rec.nextIn].prevIn = rec.prevIn;
}

void Graph::removeEdge(EdgeId e) {
    auto& rec = edges_[e];
    if (!rec.alive) return;
    if (journal_ && e < journal_->from[1]) [[unlikely]] journal_->lost = true;
    touchEdge(e);
    unlink(e);
    rec.alive = false;
    // (A compiled grammar's slot indexes its own arrays: nothing to drop here.)
    if (rec.styled || (rec.slot != kNoId && pooled(rec.kind))) dropEdgeExtras(rec, e);
    if (e < edgeBends_.size()) edgeBends_[e].clear();
    --liveEdges_;
}

void LiveNodes::iterator::settle() {
    while (n_ < g_->nodeCapacity() && !g_->nodeAlive(n_)) ++n_;
}

LiveNodes::iterator LiveNodes::end() const { return iterator(g_, static_cast<NodeId>(g_->nodeCapacity())); }

}  // namespace g2d::rt
