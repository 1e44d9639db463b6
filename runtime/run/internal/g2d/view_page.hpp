#pragma once
// The page of `g2d run --view OUT.html`: the graph in 3D (three.js, orbit
// controls), one self-contained HTML file that works offline. The model is
// plain data, read from the graph (positions, with z) and its drawing
// (colours and sizes as the SVG styles give them); the page is the model as
// inline JSON plus the embedded script (web/view/src/view.js).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/svg_writer.hpp"

namespace g2d::rt {

struct ViewNode {
    std::array<double, 3> pos{};
    double radius = 0;     // 0: not drawn (tag "none"), still an edge's end or a face's corner
    std::string color;     // CSS colour
};
struct ViewEdge {
    std::uint32_t a = 0, b = 0;   // indices into ViewModel::nodes
    std::string color;
    double radius = 0;            // G^3's thickness: the mean of the ends' `radius`; 0: a hairline
};
// A face as the triangles that draw it (triangulateFace: in its plane, each
// running the face's way round), with its own points (its corners, and the
// bends of bent sides in 2D).
struct ViewFace {
    std::uint32_t id = 0;                                  // the graph's face id
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<std::uint32_t, 3>> triangles;   // indices into `points`
    std::string color;
    double opacity = 1;                                    // style `fill_opacity`
};
struct ViewModel {
    std::string title;
    std::optional<vec3> home;      // where the camera looks from (3D grammars: --view-from, z up); none: from above
    std::vector<ViewNode> nodes;   // every live node, in id order
    std::vector<ViewEdge> edges;   // the edges drawn (not tag or stroke "none"), in id order
    std::vector<ViewFace> faces;   // the faces drawn (not tag or fill "none"), in id order
    // The graph's live elements, drawn or not, for the legend.
    std::size_t graphNodes = 0, graphEdges = 0, graphFaces = 0;
};

// Nodes: style `r` (default 0.6% of the model's diagonal), colour `fill` or
// else `stroke`; edges: `stroke`; faces: `fill` and `fill_opacity` (SVG's
// defaults otherwise); an edge's thickness is its ends' mean `radius`.
// `items` are drawItems() of `g`; `kindNames` name kinds in errors. Throws
// std::runtime_error (faceShapeMessage) for a drawn face that cannot be
// triangulated.
ViewModel viewModelOf(const Graph& g, const std::vector<DrawItem>& items, const std::string& title,
                      const std::vector<std::string>& kindNames = {});

// The model as the page's script reads it (also `g2d studio`'s 3D picture).
std::string viewModelJson(const ViewModel& model);

// The whole page. Numbers print as formatNumber does: the same model gives
// the same bytes.
std::string writeViewPage(const ViewModel& model);

}  // namespace g2d::rt
