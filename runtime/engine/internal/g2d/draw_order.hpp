#pragma once
// The order a drawing is painted in: lower z first; then, in 2D, faces,
// edges, nodes, each by id; in 3D faces, edges and nodes together (seen from
// the back first, then farther first, then faces, edges, nodes), as
// projection.hpp sets their depths. Kept as compact keys, so a graph's items can be made one at a time
// twice (once to measure the frame, once to write) instead of held in memory.
#include <cstdint>
#include <functional>
#include <vector>

#include "g2d/svg_writer.hpp"

namespace g2d::rt {

struct DrawKey {
    double z = 0, depth = 0;
    std::uint32_t id = 0;
    std::uint8_t layer = 0;      // 0 faces, 1 edges, 2 nodes
    bool turnedAway = false;
    bool inDepth = false;        // 3D: ordered by depth across the layers
};

DrawKey drawKey(const DrawItem& it);
bool drawnBefore(const DrawKey& a, const DrawKey& b);

// The order of a graph's elements, told their keys in the graph's own order
// (faces, edges, nodes, each by id: forEachLiveElement). While that order is
// already the drawing's (the usual 2D case: one z), no key is kept.
class DrawOrder {
public:
    // `earlier(keys, n)` appends the keys of the first n elements; it is
    // called once, when the first key out of order arrives.
    void add(const DrawKey& key, const std::function<void(std::vector<DrawKey>& keys, std::size_t n)>& earlier);
    // Visits the elements in drawing order.
    void visit(const Graph& g, const std::function<void(ElemClass cls, std::uint32_t id)>& fn);

private:
    std::vector<DrawKey> keys_;   // empty while the graph's order is the drawing's
    DrawKey last_;
    std::size_t count_ = 0;
};

// Calls fn(cls, id) for every live face, edge and node, in that order and by
// id, until it returns false.
void forEachLiveElement(const Graph& g, const std::function<bool(ElemClass cls, std::uint32_t id)>& fn);

}  // namespace g2d::rt
