#include "g2d/graph.hpp"

#include <algorithm>
#include <stdexcept>

namespace g2d::rt {

Graph::Graph(std::vector<KindInfo> kinds) : kinds_(std::move(kinds)), kindNodes_(kinds_.size()) {}

NodeId Graph::addNode(int kind, vec2 pos, long long age, std::vector<Value> attrs) {
    const auto id = static_cast<NodeId>(nodes_.size());
    NodeRec rec;
    rec.kind = kind;
    rec.pos = pos;
    rec.age = age;
    rec.attrs = std::move(attrs);
    rec.slotInKind = static_cast<std::uint32_t>(kindNodes_[kind].size());
    rec.slotInAll = static_cast<std::uint32_t>(allNodes_.size());
    kindNodes_[kind].push_back(id);
    allNodes_.push_back(id);
    nodes_.push_back(std::move(rec));
    ++liveNodes_;
    touchNode(id);
    return id;
}

EdgeId Graph::addEdge(int kind, NodeId src, NodeId dst, long long age, std::vector<Value> attrs) {
    if (!nodeAlive(src) || !nodeAlive(dst)) throw std::logic_error("edge endpoint is not a live node");
    const auto id = static_cast<EdgeId>(edges_.size());
    EdgeRec rec;
    rec.kind = kind;
    rec.src = src;
    rec.dst = dst;
    rec.age = age;
    rec.attrs = std::move(attrs);
    edges_.push_back(std::move(rec));
    nodes_[src].incident.push_back(id);
    if (dst != src) nodes_[dst].incident.push_back(id);
    ++liveEdges_;
    touchNode(src);
    touchNode(dst);
    return id;
}

void Graph::detach(NodeId n, EdgeId e) {
    auto& inc = nodes_[n].incident;
    auto it = std::find(inc.begin(), inc.end(), e);
    if (it != inc.end()) inc.erase(it);  // keep the order: it decides the order of matches
}

void Graph::removeEdge(EdgeId e) {
    auto& rec = edges_[e];
    if (!rec.alive) return;
    touchNode(rec.src);
    touchNode(rec.dst);
    detach(rec.src, e);
    if (rec.dst != rec.src) detach(rec.dst, e);
    rec.alive = false;
    rec.attrs.clear();
    rec.style.clear();
    --liveEdges_;
}

void Graph::removeNode(NodeId n) {
    auto& rec = nodes_[n];
    if (!rec.alive) return;
    touchNode(n);
    while (!rec.incident.empty()) {
        const EdgeId e = rec.incident.back();
        if (!edges_[e].alive) throw std::logic_error("a dead edge in an incidence list");
        removeEdge(e);
    }
    // Swap-remove from the indexes, fixing the moved node's slot.
    auto& kindList = kindNodes_[rec.kind];
    const NodeId movedK = kindList.back();
    kindList[rec.slotInKind] = movedK;
    nodes_[movedK].slotInKind = rec.slotInKind;
    kindList.pop_back();
    const NodeId movedA = allNodes_.back();
    allNodes_[rec.slotInAll] = movedA;
    nodes_[movedA].slotInAll = rec.slotInAll;
    allNodes_.pop_back();
    rec.alive = false;
    rec.attrs.clear();
    rec.style.clear();
    rec.incident.shrink_to_fit();
    --liveNodes_;
}

void Graph::reconnectEdge(EdgeId e, NodeId src, NodeId dst) {
    auto& rec = edges_[e];
    if (!rec.alive || !nodeAlive(src) || !nodeAlive(dst)) throw std::logic_error("reconnecting a dead edge or to a dead node");
    if (rec.src == src && rec.dst == dst) return;
    touchNode(rec.src);
    touchNode(rec.dst);
    touchNode(src);
    touchNode(dst);
    detach(rec.src, e);
    if (rec.dst != rec.src) detach(rec.dst, e);
    rec.src = src;
    rec.dst = dst;
    nodes_[src].incident.push_back(e);
    if (dst != src) nodes_[dst].incident.push_back(e);
}

void Graph::touchNode(NodeId n) {
    if (n >= isDirty_.size()) isDirty_.resize(std::max<std::size_t>(nodes_.size(), n + 1) * 2, false);
    if (isDirty_[n]) return;
    isDirty_[n] = true;
    dirty_.push_back(n);
}

std::vector<NodeId> Graph::takeDirty() {
    std::vector<NodeId> out;
    out.swap(dirty_);
    for (NodeId n : out) isDirty_[n] = false;
    return out;
}

int Graph::inDegree(NodeId n) const {
    int d = 0;
    for (EdgeId e : nodes_[n].incident) d += edges_[e].dst == n;
    return d;
}

int Graph::outDegree(NodeId n) const {
    int d = 0;
    for (EdgeId e : nodes_[n].incident) d += edges_[e].src == n;
    return d;
}

void Graph::setStyle(std::vector<StyleOverride>& style, const std::string& prop, Value v) {
    for (auto& s : style)
        if (s.prop == prop) { s.value = std::move(v); return; }
    style.push_back(StyleOverride{prop, std::move(v)});
}

}  // namespace g2d::rt
