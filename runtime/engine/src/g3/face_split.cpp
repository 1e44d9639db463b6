#include "g2d/face_split.hpp"

#include <algorithm>

namespace g2d::rt {

FaceSplit splitFace(Graph& g, FaceId f, std::span<const NodeId> chosen, const SplitMakers& make, long long step) {
    FaceSplit out;
    if (!g.faceAlive(f)) return out;
    std::vector<NodeId> corners;
    std::vector<std::size_t> at;   // the chosen corners' places, in order round the face
    CornerId c = g.firstCorner(f);
    for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) {
        corners.push_back(g.cornerNode(c));
        if (std::find(chosen.begin(), chosen.end(), corners.back()) != chosen.end()) at.push_back(corners.size() - 1);
    }
    const std::size_t n = corners.size(), k = at.size();
    if (k < 2 || (k >= 3 && !make.centre)) return out;
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
        out.edges.push_back(make.edge(corners[at[0]], corners[at[1]]));
        parts.push_back(arc(at[0], at[1]));
        parts.push_back(arc(at[1], at[0]));
    } else {
        out.centre = make.centre();
        for (std::size_t a : at) out.edges.push_back(make.edge(corners[a], out.centre));
        for (std::size_t j = 0; j < k; ++j) {
            parts.push_back(arc(at[j], at[(j + 1) % k]));
            parts.back().push_back(out.centre);
        }
    }
    for (const auto& part : parts) {
        out.faces.push_back(g.addFace(kind, part, step));
        make.copyFace(f, out.faces.back());
    }
    g.removeFace(f);
    return out;
}

}  // namespace g2d::rt
