#pragma once
// Automatic placement of new nodes (thesis §5.3). A daughter is drawn in the
// same sketch coordinates as its mother; a new node's sketch position is
// carried into the host by the transform that takes the mother's sketch onto
// the matched host nodes:
//
//   M, H: the sketch and host positions of all matched nodes (index-aligned)
//   R: the reference nodes: the kept ones (all matched nodes if none is kept)
//   cD = mean of R's daughter sketches, cH = mean of R's host positions
//   u_M, u_H: direction of M and of H — along the first directed mother edge
//       if there is one; else the total-least-squares line through the points
//       (principal axis of the covariance), taken pointing right (angle in
//       (-90°, 90°]) as the thesis's tool did; a point set with no principal
//       axis (isotropic: a square, a diamond) lies along the x axis;
//       w = perp_left(u)
//   s_u = extent(H along u_H) / extent(M along u_M), s_w likewise along w
//       (extent = max − min of the projections); 1 where M's extent is zero
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

// `mother` and `host`: all matched nodes; `directedEdge`: (source, target) as
// indices into them; `refDaughter` and `refHost`: R's daughter sketches and
// host positions.
PlacementFrame placementFrame(const std::vector<vec2>& mother, const std::vector<vec2>& host,
                              std::optional<std::pair<int, int>> directedEdge,
                              const std::vector<vec2>& refDaughter, const std::vector<vec2>& refHost);

}  // namespace g2d::rt
