#include "g2d/draw_order.hpp"

#include <algorithm>

namespace g2d::rt {

DrawKey drawKey(const DrawItem& it) {
    DrawKey k;
    k.z = styleNumber(it, "z", 0);
    k.depth = it.depth;
    k.id = it.id;
    k.layer = it.cls == ElemClass::Face ? 0 : it.cls == ElemClass::Edge ? 1 : 2;
    k.turnedAway = it.turnedAway;
    k.inDepth = it.inDepth;
    return k;
}

bool drawnBefore(const DrawKey& a, const DrawKey& b) {
    if (a.z != b.z) return a.z < b.z;
    if (a.inDepth) {
        // 3D (projection.hpp): what is seen from the back first (on a closed
        // surface it lies behind what is seen from the front, however big),
        // then farther first, faces, edges and nodes together, so that a
        // face hides what lies behind it; at one depth faces below edges
        // below nodes, so that a face's sides and corners stay on top of it.
        if (a.turnedAway != b.turnedAway) return a.turnedAway;
        if (a.depth != b.depth) return a.depth > b.depth;
    }
    // Faces below edges below nodes.
    if (a.layer != b.layer) return a.layer < b.layer;
    return a.id < b.id;
}

void forEachLiveElement(const Graph& g, const std::function<bool(ElemClass, std::uint32_t)>& fn) {
    // Edge ids are reused as a derivation goes on, so an edge's ends lie
    // anywhere in the node array: their records are asked for ahead of use.
    constexpr EdgeId kAhead = 16;
    for (FaceId f = 0; f < g.faceCapacity(); ++f)
        if (g.faceAlive(f) && !fn(ElemClass::Face, f)) return;
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e) {
        if (e + kAhead < g.edgeCapacity() && g.edgeAlive(e + kAhead)) {
            g.prefetchNode(g.source(e + kAhead));
            g.prefetchNode(g.target(e + kAhead));
        }
        if (g.edgeAlive(e) && !fn(ElemClass::Edge, e)) return;
    }
    for (NodeId n = 0; n < g.nodeCapacity(); ++n)
        if (g.nodeAlive(n) && !fn(ElemClass::Node, n)) return;
}

void DrawOrder::add(const DrawKey& key, const std::function<void(std::vector<DrawKey>&, std::size_t)>& earlier) {
    if (keys_.empty() && count_ > 0 && !drawnBefore(last_, key)) {
        keys_.reserve(count_ + 1);
        earlier(keys_, count_);
    }
    if (!keys_.empty()) keys_.push_back(key);
    last_ = key;
    ++count_;
}

void DrawOrder::visit(const Graph& g, const std::function<void(ElemClass, std::uint32_t)>& fn) {
    if (keys_.empty()) {
        forEachLiveElement(g, [&](ElemClass cls, std::uint32_t id) {
            fn(cls, id);
            return true;
        });
        return;
    }
    // Keys are distinct (one per element), so any sort gives the one order.
    std::sort(keys_.begin(), keys_.end(), drawnBefore);
    static constexpr ElemClass kClassOfLayer[] = {ElemClass::Face, ElemClass::Edge, ElemClass::Node};
    for (const DrawKey& k : keys_) fn(kClassOfLayer[k.layer], k.id);
}

}  // namespace g2d::rt
