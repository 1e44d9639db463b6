#include "g2d/connected_guard.hpp"

#include <algorithm>

namespace g2d::rt {

int ConnectedGuard::rootOf(int front) {
    while (parent_[static_cast<std::size_t>(front)] != front)
        front = parent_[static_cast<std::size_t>(front)] = parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(front)])];
    return front;
}

bool ConnectedGuard::keepsConnected(const Graph& g, const DaughterShape& shape, Match m) {
    const int cap = static_cast<int>(g.nodeCapacity());
    const std::size_t vertices = static_cast<std::size_t>(cap + shape.newNodes);
    if (deletedNode_.size() < g.nodeCapacity()) deletedNode_.resize(g.nodeCapacity(), 0);
    if (deletedEdge_.size() < g.edgeCapacity()) deletedEdge_.resize(g.edgeCapacity(), 0);
    if (owner_.size() < vertices) owner_.resize(vertices, -1);
    std::vector<NodeId> goneNodes;
    std::vector<EdgeId> goneEdges;
    for (int p : shape.deletedNodes) goneNodes.push_back(m.nodes[p]);
    for (int p : shape.deletedEdges) goneEdges.push_back(m.edges[p]);
    for (NodeId n : goneNodes) deletedNode_[n] = 1;
    for (EdgeId e : goneEdges) deletedEdge_[e] = 1;

    const long long left = static_cast<long long>(g.nodeCount()) - static_cast<long long>(goneNodes.size()) + shape.newNodes;
    // The touched nodes: kept match nodes, new ones, surviving ends of what goes.
    touched_.clear();
    auto vertexOf = [&](int end) { return end >= 0 ? static_cast<int>(m.nodes[end]) : cap + (-1 - end); };
    for (const auto& e : shape.newEdges) touched_.push_back(vertexOf(e.src)), touched_.push_back(vertexOf(e.dst));
    for (int k = 0; k < shape.newNodes; ++k) touched_.push_back(cap + k);
    for (EdgeId e : goneEdges) touched_.push_back(static_cast<int>(g.source(e))), touched_.push_back(static_cast<int>(g.target(e)));
    for (NodeId n : goneNodes)
        for (EdgeId e : g.incident(n)) touched_.push_back(static_cast<int>(g.source(e) == n ? g.target(e) : g.source(e)));
    touched_.erase(std::remove_if(touched_.begin(), touched_.end(), [&](int v) { return v < cap && deletedNode_[static_cast<std::size_t>(v)]; }),
                   touched_.end());
    std::sort(touched_.begin(), touched_.end());
    touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());

    std::vector<std::pair<int, int>> added;   // new edges between vertices
    for (const auto& e : shape.newEdges) added.push_back({vertexOf(e.src), vertexOf(e.dst)});

    // One breadth-first search from all the touched nodes at once: each
    // vertex is owned by the front that reached it first, fronts that meet
    // join, and a set of joined fronts with nothing left to visit is a piece
    // without the others.
    bool ok = left > 0;
    visited_.clear();
    if (ok && touched_.size() > 1) {
        const int fronts = static_cast<int>(touched_.size());
        parent_.assign(static_cast<std::size_t>(fronts), 0);
        pending_.assign(static_cast<std::size_t>(fronts), 1);   // per set root: vertices queued
        queue_.clear();
        for (int f = 0; f < fronts; ++f) {
            parent_[static_cast<std::size_t>(f)] = f;
            owner_[static_cast<std::size_t>(touched_[static_cast<std::size_t>(f)])] = f;
            visited_.push_back(touched_[static_cast<std::size_t>(f)]);
            queue_.push_back(touched_[static_cast<std::size_t>(f)]);
        }
        int sets = fronts;
        auto reach = [&](int f, int w) {
            const int o = owner_[static_cast<std::size_t>(w)];
            if (o < 0) {
                owner_[static_cast<std::size_t>(w)] = f;
                visited_.push_back(w);
                queue_.push_back(w);
                ++pending_[static_cast<std::size_t>(rootOf(f))];
            } else if (const int ro = rootOf(o), rf = rootOf(f); ro != rf) {
                parent_[static_cast<std::size_t>(ro)] = rf;
                pending_[static_cast<std::size_t>(rf)] += pending_[static_cast<std::size_t>(ro)];
                --sets;
            }
        };
        for (std::size_t head = 0; sets > 1; ++head) {
            const int v = queue_[head];
            const int f = owner_[static_cast<std::size_t>(v)];
            if (v < cap)
                for (EdgeId e : g.incident(static_cast<NodeId>(v))) {
                    if (deletedEdge_[e]) continue;
                    const NodeId w = g.source(e) == static_cast<NodeId>(v) ? g.target(e) : g.source(e);
                    if (!deletedNode_[w]) reach(f, static_cast<int>(w));
                }
            for (const auto& [a, b] : added) {
                if (a == v) reach(f, b);
                if (b == v) reach(f, a);
            }
            if (sets > 1 && --pending_[static_cast<std::size_t>(rootOf(f))] == 0) {
                ok = false;   // this set is closed
                break;
            }
        }
    }
    for (int v : visited_) owner_[static_cast<std::size_t>(v)] = -1;
    for (NodeId n : goneNodes) deletedNode_[n] = 0;
    for (EdgeId e : goneEdges) deletedEdge_[e] = 0;
    return ok;
}

}  // namespace g2d::rt
