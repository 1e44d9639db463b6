#pragma once
// Decorations (Merrell 2023, Appendix B: "an optional post-processing
// step"): images or shapes placed at a node, tiled along an edge, or
// scattered or laid on a grid over a face, configured by `decor_*` style
// properties (docs/language.md §6.1):
//
//   decor_href            an image: each placement draws it
//   decor_tag             image | rect | circle (default image with an href;
//                         without either, nothing is placed)
//   decor_width/_height   the placement's size (node, face: 0.5 × 0.5; edge:
//                         the tile's length along it × 0.2 across)
//   decor_rotate          degrees, counter-clockwise (edges: from their direction)
//   decor_every           edges: the tile length (max(1, round(L / every))
//                         tiles fill an edge of drawn length L, Merrell's brush
//                         tiling); faces: a grid's spacing, from the origin
//   decor_density         faces: placements per unit of area, scattered at
//                         random (dart throwing with a least distance)
//   decor_offset          edges: shifts the tiles to the left of the edge
//   decor_PROP            any other: the SVG attribute PROP of each placement
//
// Placements depend on the drawn geometry and the element's class and id
// only (a face's scatter draws from an Rng seeded by its id), so the same
// drawing decorates the same way, interpreted or compiled.
#include <string_view>
#include <vector>

#include "g2d/svg_writer.hpp"

namespace g2d::rt {

// At most this many placements per element (a tiny spacing on a big face).
inline constexpr std::size_t kMaxDecorations = 10000;

struct Placement {
    vec2 centre;
    double degrees = 0;   // counter-clockwise
    double width = 0, height = 0;
};

enum class DecorShape { None, Image, Rect, Circle };

DecorShape decorShape(const DrawItem& it);

// Where the item's decoration goes (empty when it has none).
std::vector<Placement> decorPlacements(const DrawItem& it);

// Whether `prop` configures the decoration (the item's own element skips it),
// and whether it places it (the placements' elements skip those too).
inline bool isDecorProp(std::string_view prop) { return prop.size() > 6 && prop.substr(0, 6) == "decor_"; }
bool isPlacementProp(std::string_view prop);

}  // namespace g2d::rt
