#include "g2d/face_split.hpp"

namespace g2d::rt {

FaceSplit splitFace(Graph& g, FaceId f, std::span<const NodeId> corners, std::span<const std::uint8_t> chosen, vec3 centre,
                    int nodeKind, int edgeKind, long long step, const std::function<void(FaceId from, FaceId to)>& copyFace) {
    FaceSplit out;
    const std::size_t n = corners.size();
    std::vector<std::size_t> at;   // the chosen corners' places, in order round the face
    for (std::size_t i = 0; i < n; ++i)
        if (chosen[i]) at.push_back(i);
    const std::size_t k = at.size();
    if (k < 2 || !g.faceAlive(f)) return out;
    if (k == 2 && (at[1] - at[0] == 1 || at[1] - at[0] == n - 1)) return out;   // neighbours: nothing to cut
    // The corners from chosen corner a round to chosen corner b (both included).
    auto arc = [&](std::size_t a, std::size_t b) {
        std::vector<NodeId> part;
        for (std::size_t i = a;; i = (i + 1) % n) {
            part.push_back(corners[i]);
            if (i == b) break;
        }
        return part;
    };
    const int kind = g.faceKind(f);
    std::vector<std::vector<NodeId>> parts;
    if (k == 2) {
        out.edges.push_back(g.addEdge(edgeKind, corners[at[0]], corners[at[1]], step));
        parts.push_back(arc(at[0], at[1]));
        parts.push_back(arc(at[1], at[0]));
    } else {
        out.centre = g.addNode(nodeKind, centre, step);
        for (std::size_t a : at) out.edges.push_back(g.addEdge(edgeKind, corners[a], out.centre, step));
        for (std::size_t j = 0; j < k; ++j) {
            parts.push_back(arc(at[j], at[(j + 1) % k]));
            parts.back().push_back(out.centre);
        }
    }
    for (const auto& part : parts) {
        out.faces.push_back(g.addFace(kind, part, step));
        copyFace(f, out.faces.back());
    }
    g.removeFace(f);
    return out;
}

}  // namespace g2d::rt
