#pragma once
// The host graph: nodes and edges with stable ids (never reused), kinds,
// positions, typed attribute slots, per-element style overrides and ages.
// Per-kind indexes and per-node incidence lists make every step of a search
// O(1); deleting an element is O(degree).
//
// Element classes are explicit (nodes, edges) so that faces can be added as
// a third class with their own index and incidences.
#include <cstdint>
#include <string>
#include <vector>

#include "g2d/value.hpp"
#include "g2d/vec_math.hpp"

namespace g2d::rt {

using NodeId = std::uint32_t;
using EdgeId = std::uint32_t;
inline constexpr std::uint32_t kNoId = 0xffffffffu;

struct KindInfo {
    bool isEdge = false;
    bool directed = false;
};

struct StyleOverride {
    std::string prop;
    Value value;
};

class Graph {
public:
    explicit Graph(std::vector<KindInfo> kinds);

    NodeId addNode(int kind, vec2 pos, long long age, std::vector<Value> attrs);
    EdgeId addEdge(int kind, NodeId src, NodeId dst, long long age, std::vector<Value> attrs);
    void removeEdge(EdgeId e);
    void removeNode(NodeId n);                  // with its incident (dangling) edges
    void reconnectEdge(EdgeId e, NodeId src, NodeId dst);

    bool nodeAlive(NodeId n) const { return n < nodes_.size() && nodes_[n].alive; }
    bool edgeAlive(EdgeId e) const { return e < edges_.size() && edges_[e].alive; }
    std::size_t nodeCount() const { return liveNodes_; }
    std::size_t edgeCount() const { return liveEdges_; }
    std::size_t nodeCapacity() const { return nodes_.size(); }  // ids are below this
    std::size_t edgeCapacity() const { return edges_.size(); }

    int nodeKind(NodeId n) const { return nodes_[n].kind; }
    vec2 pos(NodeId n) const { return nodes_[n].pos; }
    void setPos(NodeId n, vec2 p) { nodes_[n].pos = p; touchNode(n); }
    long long nodeAge(NodeId n) const { return nodes_[n].age; }
    const Value& nodeAttr(NodeId n, int i) const { return nodes_[n].attrs[i]; }
    void setNodeAttr(NodeId n, int i, Value v) { nodes_[n].attrs[i] = std::move(v); touchNode(n); }
    const std::vector<StyleOverride>& nodeStyle(NodeId n) const { return nodes_[n].style; }
    // A back end's own handle for the element's attributes (compiled grammars
    // keep them in typed arrays); kNoId until set.
    std::uint32_t nodeSlot(NodeId n) const { return nodes_[n].slot; }
    void setNodeSlot(NodeId n, std::uint32_t slot) { nodes_[n].slot = slot; }
    void setNodeStyle(NodeId n, const std::string& prop, Value v) { setStyle(nodes_[n].style, prop, std::move(v)); }

    int edgeKind(EdgeId e) const { return edges_[e].kind; }
    NodeId source(EdgeId e) const { return edges_[e].src; }
    NodeId target(EdgeId e) const { return edges_[e].dst; }
    long long edgeAge(EdgeId e) const { return edges_[e].age; }
    const Value& edgeAttr(EdgeId e, int i) const { return edges_[e].attrs[i]; }
    void setEdgeAttr(EdgeId e, int i, Value v) { edges_[e].attrs[i] = std::move(v); touchEdge(e); }
    const std::vector<StyleOverride>& edgeStyle(EdgeId e) const { return edges_[e].style; }
    std::uint32_t edgeSlot(EdgeId e) const { return edges_[e].slot; }
    void setEdgeSlot(EdgeId e, std::uint32_t slot) { edges_[e].slot = slot; }
    void setEdgeStyle(EdgeId e, const std::string& prop, Value v) { setStyle(edges_[e].style, prop, std::move(v)); }

    // Live nodes of one kind, or of every kind; order is deterministic.
    const std::vector<NodeId>& nodesOfKind(int kind) const { return kindNodes_[kind]; }
    const std::vector<NodeId>& allNodes() const { return allNodes_; }
    // Edges touching a node (a self-loop appears once).
    const std::vector<EdgeId>& incident(NodeId n) const { return nodes_[n].incident; }
    int degree(NodeId n) const { return static_cast<int>(nodes_[n].incident.size()); }
    int inDegree(NodeId n) const;
    int outDegree(NodeId n) const;

    const std::vector<KindInfo>& kinds() const { return kinds_; }

    // Change tracking for incremental matching: every node that was created,
    // deleted or changed, or whose incident edges were, since takeDirty().
    void touchNode(NodeId n);
    void touchEdge(EdgeId e) { touchNode(edges_[e].src); touchNode(edges_[e].dst); }
    std::vector<NodeId> takeDirty();

private:
    struct NodeRec {
        int kind = -1;
        bool alive = true;
        vec2 pos{0, 0};
        long long age = 0;
        std::uint32_t slotInKind = 0, slotInAll = 0;
        std::uint32_t slot = kNoId;
        std::vector<EdgeId> incident;
        std::vector<Value> attrs;
        std::vector<StyleOverride> style;
    };
    struct EdgeRec {
        int kind = -1;
        bool alive = true;
        NodeId src = kNoId, dst = kNoId;
        std::uint32_t slot = kNoId;
        long long age = 0;
        std::vector<Value> attrs;
        std::vector<StyleOverride> style;
    };

    static void setStyle(std::vector<StyleOverride>& style, const std::string& prop, Value v);
    void detach(NodeId n, EdgeId e);

    std::vector<KindInfo> kinds_;
    std::vector<NodeRec> nodes_;
    std::vector<EdgeRec> edges_;
    std::vector<std::vector<NodeId>> kindNodes_;
    std::vector<NodeId> allNodes_;
    std::size_t liveNodes_ = 0, liveEdges_ = 0;
    std::vector<NodeId> dirty_;
    std::vector<bool> isDirty_;
};

}  // namespace g2d::rt
