#include "g2d/node_merge.hpp"

#include <algorithm>

namespace g2d::rt {

namespace {

// Splits a cyclic node list at repeated nodes into simple cycles (positions
// into `nodes`, each in cyclic order), the one holding position 0 first.
// Splitting at nodes[i] == nodes[j] (i < j, the first such pair) gives the
// cycle i .. j-1 and the cycle j .. end, 0 .. i-1, each split again.
std::vector<std::vector<std::size_t>> simpleCycles(const std::vector<NodeId>& nodes, std::vector<std::size_t> at = {}) {
    if (at.empty())
        for (std::size_t k = 0; k < nodes.size(); ++k) at.push_back(k);
    for (std::size_t i = 0; i < at.size(); ++i)
        for (std::size_t j = i + 1; j < at.size(); ++j) {
            if (nodes[at[i]] != nodes[at[j]]) continue;
            std::vector<std::size_t> inner(at.begin() + static_cast<long>(i), at.begin() + static_cast<long>(j));
            std::vector<std::size_t> outer(at.begin() + static_cast<long>(j), at.end());
            outer.insert(outer.end(), at.begin(), at.begin() + static_cast<long>(i));
            auto out = simpleCycles(nodes, std::move(outer));
            auto more = simpleCycles(nodes, std::move(inner));
            out.insert(out.end(), more.begin(), more.end());
            // The part holding position 0 first.
            const auto holdsZero = [](const std::vector<std::size_t>& p) { return std::find(p.begin(), p.end(), 0) != p.end(); };
            std::stable_partition(out.begin(), out.end(), holdsZero);
            return out;
        }
    return {at};
}

std::vector<EdgeId> incidentEdges(const Graph& g, NodeId n) {
    std::vector<EdgeId> out;
    for (EdgeId e : g.incident(n)) out.push_back(e);
    return out;
}

}  // namespace

NodeMerger::NodeMerger(const Graph& g, double cellSize, CopyFace copyFace)
    : grid_(cellSize), copyFace_(std::move(copyFace)) {
    grid_.reserve(g.nodeCount());
    for (NodeId n : g.allNodes()) index(n, g.pos3(n));
}

void NodeMerger::index(NodeId n, vec3 p) {
    if (n >= at_.size()) {
        at_.resize(n + 1 + n / 2);
        indexed_.resize(at_.size(), 0);
    }
    if (indexed_[n]) {
        grid_.move(n, at_[n], p);
    } else {
        grid_.insert(n, p);
        indexed_[n] = 1;
    }
    at_[n] = p;
}

void NodeMerger::unindex(NodeId n) {
    if (n >= indexed_.size() || !indexed_[n]) return;
    grid_.remove(n, at_[n]);
    indexed_[n] = 0;
}

void NodeMerger::sync(const Graph& g) {
    candidates_.clear();
    for (NodeId n : g.changedNodes()) {
        if (!g.nodeAlive(n)) {
            unindex(n);
            continue;
        }
        const vec3 p = g.pos3(n);
        const bool known = n < indexed_.size() && indexed_[n];
        if (known && at_[n] == p) continue;
        index(n, p);
        candidates_.push_back(n);
    }
}

std::size_t NodeMerger::mergeChanged(Graph& g, double tolerance) {
    std::sort(candidates_.begin(), candidates_.end());
    candidates_.erase(std::unique(candidates_.begin(), candidates_.end()), candidates_.end());
    std::vector<SpatialGrid::Hit> hits;
    std::size_t merged = 0;
    for (NodeId n : candidates_) {
        if (!g.nodeAlive(n)) continue;
        grid_.within(g.pos3(n), tolerance, hits);
        for (const auto& hit : hits) {
            if (hit.id == n || !g.nodeAlive(hit.id)) continue;
            // The lower id survives; hits come in id order.
            const NodeId keep = std::min<NodeId>(hit.id, n), gone = std::max<NodeId>(hit.id, n);
            merge(g, keep, gone);
            ++merged;
            break;
        }
    }
    candidates_.clear();
    return merged;
}

void NodeMerger::merge(Graph& g, NodeId keep, NodeId gone) {
    g.setPos(keep, (g.pos3(keep) + g.pos3(gone)) / 2.0);
    const double radius = (g.radius(keep) + g.radius(gone)) / 2;
    if (radius != g.radius(keep)) g.setRadius(keep, radius);
    index(keep, g.pos3(keep));
    // Edges: those joining the two go (2); the rest move their end to keep.
    const std::vector<EdgeId> edges = incidentEdges(g, gone);
    for (EdgeId e : edges) {
        const NodeId s = g.source(e), t = g.target(e);
        const NodeId s2 = s == gone ? keep : s, t2 = t == gone ? keep : t;
        if (s2 == keep && t2 == keep) g.removeEdge(e);
        else g.reconnectEdge(e, s2, t2);
    }
    mergeDuplicateEdges(g, keep);
    // Faces: gone's corners become keep's, then each face is repaired (4-6).
    std::vector<CornerId> corners;
    for (CornerId c = g.firstCornerAt(gone); c != kNoId; c = g.nextCornerAt(c)) corners.push_back(c);
    std::vector<FaceId> faces;
    for (CornerId c : corners) {
        faces.push_back(g.cornerFace(c));
        g.moveCorner(c, keep);
    }
    for (FaceId f : faces) repairFace(g, f);
    removeDuplicateFaces(g, keep);
    for (FaceId f : faces)
        if (g.faceAlive(f)) g.faceReshaped(f);
    unindex(gone);
    g.removeNode(gone);
}

void NodeMerger::mergeDuplicateEdges(Graph& g, NodeId n) {
    std::vector<EdgeId> edges = incidentEdges(g, n);
    std::sort(edges.begin(), edges.end());
    auto other = [&](EdgeId e) { return g.source(e) == n ? g.target(e) : g.source(e); };
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (!g.edgeAlive(edges[i])) continue;
        for (std::size_t j = i + 1; j < edges.size(); ++j)
            if (g.edgeAlive(edges[j]) && g.edgeKind(edges[j]) == g.edgeKind(edges[i]) && other(edges[j]) == other(edges[i]))
                g.removeEdge(edges[j]);
    }
}

void NodeMerger::repairFace(Graph& g, FaceId f) {
    if (!g.faceAlive(f)) return;
    // A node twice in a row (5), the last and first corners included, is kept once.
    const CornerId first = g.firstCorner(f);
    for (CornerId c = first;;) {
        const CornerId next = g.nextCorner(c);
        if (g.cornerCount(f) > 1 && next != first && g.cornerNode(next) == g.cornerNode(c)) {
            g.removeCorner(next);
            continue;
        }
        if (next == first) {
            if (c != first && g.cornerNode(c) == g.cornerNode(first)) g.removeCorner(c);
            break;
        }
        c = next;
    }
    std::vector<CornerId> cycle;
    std::vector<NodeId> nodes;
    CornerId c = g.firstCorner(f);
    for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) {
        cycle.push_back(c);
        nodes.push_back(g.cornerNode(c));
    }
    // A node twice apart (5, 6): the face splits into simple cycles; the one
    // with its first corner stays f, the others are new faces.
    const std::vector<std::vector<std::size_t>> parts = simpleCycles(nodes);
    if (parts.size() > 1) {
        std::vector<std::uint8_t> keep(cycle.size(), 0);
        for (std::size_t k : parts[0]) keep[k] = 1;
        for (std::size_t k = 0; k < cycle.size(); ++k)
            if (!keep[k]) g.removeCorner(cycle[k]);
        for (std::size_t p = 1; p < parts.size(); ++p) {
            if (parts[p].size() < 3) continue;
            std::vector<NodeId> corners;
            for (std::size_t k : parts[p]) corners.push_back(nodes[k]);
            const FaceId part = g.addFace(g.faceKind(f), corners, g.faceAge(f));
            g.setFaceGeneration(part, g.faceGeneration(f));   // a part of f, as old as f
            copyFace_(g, f, part);
        }
    }
    if (g.cornerCount(f) < 3) g.removeFace(f);   // (4)
}

void NodeMerger::removeDuplicateFaces(Graph& g, NodeId n) {
    std::vector<FaceId> faces;
    for (CornerId c = g.firstCornerAt(n); c != kNoId; c = g.nextCornerAt(c)) faces.push_back(g.cornerFace(c));
    std::sort(faces.begin(), faces.end());
    auto cornerSet = [&](FaceId f) {
        std::vector<NodeId> s;
        CornerId c = g.firstCorner(f);
        for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) s.push_back(g.cornerNode(c));
        std::sort(s.begin(), s.end());
        return s;
    };
    for (std::size_t i = 0; i < faces.size(); ++i) {
        if (!g.faceAlive(faces[i])) continue;
        const auto a = cornerSet(faces[i]);
        for (std::size_t j = i + 1; j < faces.size(); ++j)
            if (g.faceAlive(faces[j]) && cornerSet(faces[j]) == a) g.removeFace(faces[j]);
    }
}

}  // namespace g2d::rt
