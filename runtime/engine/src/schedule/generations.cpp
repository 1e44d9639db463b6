#include "g2d/generations.hpp"

#include <algorithm>

#include "g2d/match_set.hpp"

namespace g2d::rt {

long long highestGeneration(const Match& m, int nodes, int edges, int faces, const Graph& g) {
    long long highest = 0;
    for (int i = 0; i < nodes; ++i) highest = std::max(highest, g.nodeGeneration(m.nodes[i]));
    for (int i = 0; i < edges; ++i) highest = std::max(highest, g.edgeGeneration(m.edges[i]));
    for (int i = 0; i < faces; ++i) highest = std::max(highest, g.faceGeneration(m.faces[i]));
    return highest;
}

void GenerationStamps::prepared(const Match& m, int nodes, int edges, int faces, const Graph& g) {
    if (queue_.empty()) {
        // Preparing creates nothing: the commit's new ids begin here.
        nodesFrom_ = static_cast<NodeId>(g.nodeCapacity());
        edgesFrom_ = static_cast<EdgeId>(g.edgeCapacity());
        facesFrom_ = static_cast<FaceId>(g.faceCapacity());
    }
    queue_.push_back(highestGeneration(m, nodes, edges, faces, g) + 1);
}

void GenerationStamps::applied(Graph& g) {
    if (next_ >= queue_.size()) return;   // an application prepared before tracking began
    g.setGenerationsFrom(nodesFrom_, edgesFrom_, facesFrom_, queue_[next_]);
    nodesFrom_ = static_cast<NodeId>(g.nodeCapacity());
    edgesFrom_ = static_cast<EdgeId>(g.edgeCapacity());
    facesFrom_ = static_cast<FaceId>(g.faceCapacity());
    if (++next_ == queue_.size()) clear();
}

void GenerationStamps::clear() {
    queue_.clear();
    next_ = 0;
}

}  // namespace g2d::rt
