#include "g2d/obj_writer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "g2d/ops.hpp"

namespace g2d::rt {

std::string writeObj(const Graph& g, const JsonSchema& schema) {
    std::string out = "# g2d: " + std::to_string(g.nodeCount()) + " nodes, " + std::to_string(g.edgeCount()) + " edges, " +
                      std::to_string(g.faceCount()) + " faces\n";
    // OBJ indices are 1-based in write order; node ids have gaps after deletions.
    std::vector<std::uint32_t> index(g.nodeCapacity(), 0);
    std::uint32_t next = 1;
    for (NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        const vec3 p = g.pos3(n);
        if (!isFinitePosition(p)) throw std::runtime_error("node " + std::to_string(n) + "'s position is not finite");
        out += "v " + formatNumber(p.x) + " " + formatNumber(p.y) + " " + formatNumber(p.z) + "\n";
        index[n] = next++;
    }
    for (std::size_t k = 0; k < g.kinds().size(); ++k) {
        if (g.kinds()[k].cls != ElemClass::Face) continue;
        std::vector<FaceId> faces(g.facesOfKind(static_cast<int>(k)).begin(), g.facesOfKind(static_cast<int>(k)).end());
        if (faces.empty()) continue;
        std::sort(faces.begin(), faces.end());
        out += "g " + schema.kindNames[k] + "\n";
        for (FaceId f : faces) {
            out += "f";
            CornerId c = g.firstCorner(f);
            for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) out += " " + std::to_string(index[g.cornerNode(c)]);
            out += "\n";
        }
    }
    if (g.edgeCount() > 0) {
        out += "g edges\n";
        for (EdgeId e = 0; e < g.edgeCapacity(); ++e)
            if (g.edgeAlive(e)) out += "l " + std::to_string(index[g.source(e)]) + " " + std::to_string(index[g.target(e)]) + "\n";
    }
    return out;
}

}  // namespace g2d::rt
