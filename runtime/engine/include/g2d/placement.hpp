#pragma once
// Automatic placement of new nodes (thesis §5.3), as the thesis's tool
// computes it. A daughter is drawn in the same sketch coordinates as its
// mother; a new node's sketch position is carried into the host:
//
//   M, H: the sketch and host positions of all matched nodes (index-aligned)
//   R: the reference nodes: the kept ones (all matched nodes if none is kept)
//   cD = mean of R's daughter sketches, cH = mean of R's host positions
//   θ_M, θ_H: the direction of M and of H — of the first directed mother edge
//       if there is one; else of the total-least-squares line through the
//       points, taken pointing right (angle in (-90°, 90°]); 0 for a point set
//       with no principal axis (a square, a diamond, one point)
//   Δ = θ_H − θ_M, and Rot the rotation by Δ
//   s_x = x-extent(H) / x-extent(Rot·M), s_y likewise (extent = max − min);
//       1 where Rot·M has no extent (1e-9 of the larger one)
//   place(d) = cH + (s_x, s_y) ⊙ Rot·(d − cD)
//
// So new nodes follow the match's translation, rotation and stretch (Fig.
// 5.3: a production that doubles an edge doubles any edge); the stretch is
// per world axis, as in the tool: across a horizontal line it is 1, along a
// slanted one it is uniform.
#include <optional>
#include <span>
#include <utility>

#include "g2d/vec_math.hpp"

namespace g2d::rt {

struct PlacementFrame {
    vec2 cD{0, 0}, cH{0, 0};
    double cosA = 1, sinA = 0;    // the rotation Δ
    double sx = 1, sy = 1;
    double z = 0;                 // 3D: the mean z of R's host positions
    vec2 place(vec2 sketch) const;
    vec3 place3(vec2 sketch) const {
        const vec2 p = place(sketch);
        return {p.x, p.y, z};
    }
};

// `mother` and `host`: all matched nodes; `directedEdge`: (source, target) as
// indices into them; `refDaughter` and `refHost`: R's daughter sketches and
// host positions; `refZ`: R's host z (3D grammars: a new node is placed by
// the rule above in plan, xy, at the mean height of R; empty in 2D).
PlacementFrame placementFrame(std::span<const vec2> mother, std::span<const vec2> host,
                              std::optional<std::pair<int, int>> directedEdge,
                              std::span<const vec2> refDaughter, std::span<const vec2> refHost,
                              std::span<const double> refZ = {});

}  // namespace g2d::rt
