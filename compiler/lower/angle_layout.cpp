#include "lower/angle_layout.hpp"

namespace g2d::lower {

std::optional<rt::AngleLayoutSpec> angleLayoutSpec(const ir::Program& prog) {
    if (!prog.angleLayout) return std::nullopt;
    const ir::AngleLayout& l = *prog.angleLayout;
    rt::AngleLayoutSpec spec;
    spec.settings.proposals = l.proposals;
    spec.settings.samples = l.samples;
    spec.connected = l.connected;
    spec.bendSegment = l.bendSegment;
    spec.bendSmooth = l.bendSmooth;
    if (l.clearance > 0) spec.settings.separation = l.clearance;
    spec.settings.canvasLo = rt::vec2(l.canvasMin[0], l.canvasMin[1]);
    spec.settings.canvasHi = rt::vec2(l.canvasMax[0], l.canvasMax[1]);
    for (const auto& k : prog.kinds) {
        rt::EdgeGeometry e;
        if (k.layout)
            e = rt::EdgeGeometry{true, k.layout->angle, k.layout->minLength, k.layout->maxLength, k.layout->left, k.layout->right, k.layout->unit,
                                 k.layout->bend};
        spec.kinds.push_back(e);
    }
    return spec;
}

}  // namespace g2d::lower
