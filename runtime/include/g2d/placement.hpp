#pragma once
// Automatic placement of new nodes (thesis §5.3). A daughter is drawn in the
// same sketch coordinates as its mother; a new node's sketch position is
// carried into the host by the transform that takes the mother's sketch onto
// the matched host nodes:
//
//   reference nodes R: the kept mother nodes (all mother nodes if none is kept)
//   cD = mean of R's daughter sketches, cH = mean of R's host positions
//   u_M, u_H: direction of the mother sketch and of the host match — along the
//       first directed mother edge if there is one, else the total-least-
//       squares line through R (principal axis of the covariance), oriented
//       like the vector from R's first to its last node;
//       w = perp_left(u)
//   s_u = extent_H(u_H) / extent_M(u_M), s_w likewise along w (extent = max −
//       min of the projections); an undefined ratio (zero mother extent) takes
//       the other one, and 1 if both are undefined
//   place(d) = cH + s_u·⟨d − cD, u_M⟩·u_H + s_w·⟨d − cD, w_M⟩·w_H
//
// So the new nodes follow the match's translation, rotation and per-axis
// stretch (Fig. 5.3: a production that doubles an edge doubles any edge).
#include <optional>
#include <utility>
#include <vector>

#include "g2d/vec_math.hpp"

namespace g2d::rt {

struct PlacementFrame {
    vec2 cD{0, 0}, cH{0, 0};
    vec2 uM{1, 0}, wM{0, 1}, uH{1, 0}, wH{0, 1};
    double su = 1, sw = 1;
    vec2 place(vec2 sketch) const;
};

// `mother`, `daughter` and `host` are R's positions, index-aligned;
// `directedEdge` is (source, target) as indices into them.
PlacementFrame placementFrame(const std::vector<vec2>& mother, const std::vector<vec2>& daughter,
                              const std::vector<vec2>& host,
                              std::optional<std::pair<int, int>> directedEdge);

}  // namespace g2d::rt
