#include "emit/cpp_angle_layout.hpp"

#include "emit/cpp_expr.hpp"

namespace g2d::emit {

namespace {

std::string num(double x) { return cppLiteral(ir::Value{x}, ir::kFloatType); }
std::string num(int x) { return std::to_string(x); }

}  // namespace

std::string angleLayoutOverride(const std::optional<rt::AngleLayoutSpec>& spec) {
    if (!spec) return "";
    const auto& s = spec->settings;
    std::string kinds;
    for (const auto& k : spec->kinds)
        kinds += "            {" + std::string(k.given ? "true" : "false") + ", " + num(k.angle) + ", " + num(k.minLength) + ", " +
                 num(k.maxLength) + ", " + num(k.left) + ", " + num(k.right) + ", " + num(k.unit) + ", " + num(k.bend) + "},\n";
    return "    const AngleLayoutSpec* angleLayout() const override {\n"
           "        static const AngleLayoutSpec spec{\n"
           "            DrawingSettings{" + num(s.proposals) + ", " + num(s.samples) + ", vec2(" + num(s.canvasLo.x) + ", " + num(s.canvasLo.y) +
           "), vec2(" + num(s.canvasHi.x) + ", " + num(s.canvasHi.y) + "), " + num(s.separation) + "},\n"
           "            " + (spec->connected ? "true" : "false") + ",\n"
           "            {\n" + kinds + "            },\n"
           "            " + num(spec->bendSegment) + ", " + num(spec->bendSmooth) + "};\n"
           "        return &spec;\n    }\n\n";
}

}  // namespace g2d::emit
