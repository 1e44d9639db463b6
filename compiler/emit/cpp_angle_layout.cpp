#include "emit/cpp_angle_layout.hpp"

#include "emit/cpp_expr.hpp"
#include "lower/angle_layout.hpp"

namespace g2d::emit {

namespace {

std::string num(double x) { return cppLiteral(ir::Value{x}, ir::kFloatType); }
std::string num(int x) { return std::to_string(x); }

std::string ints(const std::vector<int>& v) {
    std::string out = "std::vector<int>{";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + num(v[i]);
    return out + "}";
}

}  // namespace

std::string daughterShapesText(const std::vector<rt::DaughterShape>& shapes, const std::string& in) {
    std::string out;
    for (const auto& s : shapes) {
        std::string edges;
        for (const auto& e : s.newEdges)
            edges += (edges.empty() ? "" : ", ") + std::string("{") + num(e.src) + ", " + num(e.dst) + ", " + num(e.kind) + "}";
        out += in + "info.shapes.push_back(DaughterShape{" + ints(s.deletedNodes) + ", " + ints(s.deletedEdges) + ", " + num(s.newNodes) +
               ", {" + edges + "}, " + ints(s.newNodeKinds) + "});\n";
    }
    return out;
}

std::string angleLayoutOverride(const ir::Program& prog) {
    const auto spec = lower::angleLayoutSpec(prog);
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
