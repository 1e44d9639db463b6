#include "g2d/export_style.hpp"

#include <algorithm>
#include <cmath>

namespace g2d::rt {

namespace {

std::string hexByte(double v) {
    const int b = static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
    constexpr char digits[] = "0123456789abcdef";
    return {digits[b / 16], digits[b % 16]};
}

// `fallback` stands for a colour the exports cannot read (a gradient's url()).
ExportMaterial material(const std::string& css, double opacity, const char* prefix, Rgba fallback) {
    ExportMaterial m;
    if (css == "none") {
        m.colour = {0, 0, 0, 0};
    } else {
        m.colour = cssColor(css).value_or(fallback);
        m.colour.a *= std::clamp(opacity, 0.0, 1.0);
    }
    m.name = prefix + hexByte(m.colour.r) + hexByte(m.colour.g) + hexByte(m.colour.b);
    if (hexByte(m.colour.a) != "ff") m.name += hexByte(m.colour.a);
    return m;
}

}  // namespace

ExportMaterial faceMaterial(const DrawItem& face) {
    constexpr double grey = 0xd9 / 255.0;
    return material(styleText(face, "fill", "#d9d9d9"), styleNumber(face, "fill_opacity", 1), "fill_", {grey, grey, grey, 1});
}

ExportMaterial edgeMaterial(const DrawItem& edge) {
    return material(styleText(edge, "stroke", "black"), styleNumber(edge, "stroke_opacity", 1), "stroke_", {0, 0, 0, 1});
}

}  // namespace g2d::rt
