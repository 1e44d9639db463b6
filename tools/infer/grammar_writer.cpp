#include "infer/grammar_writer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include "infer/label_colours.hpp"
#include "infer/rule_pieces.hpp"
#include "infer/rule_sides.hpp"

namespace g2d::infer {
namespace {

// Up to 6 significant digits, no trailing zeros, never "-0": people read and edit these.
std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return std::string(buf) == "-0" ? "0" : buf;
}

// The shortest text that reads back as the same double: directions and
// lengths must close the example's loops exactly, or the drawing step's
// system loses its freedom (a rounded angle makes a triangle rigid at size 0).
std::string exact(double v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    const std::string out(buf, r.ptr);
    return out == "-0" ? "0" : out;
}

double roundSignificant(double v, int digits) {
    if (!(v > 0)) return 0;
    const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(v)));
    return std::round(v * scale) / scale;
}

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c == '\n' || c == '\r' ? ' ' : c;
    }
    return out + "\"";
}

// The example's drawing: its bounding box, each side at least `least` (a straight line still has room across it).
std::pair<Point, Point> drawingBox(const ExampleShape& s, double least) {
    Point lo{1e300, 1e300}, hi{-1e300, -1e300};
    for (const Point& p : s.vertices) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    if (s.vertices.empty()) return {{0, 0}, {least, least}};
    const Point grow{std::max(0.0, least - (hi.x - lo.x)) / 2, std::max(0.0, least - (hi.y - lo.y)) / 2};
    return {{lo.x - grow.x, lo.y - grow.y}, {hi.x + grow.x, hi.y + grow.y}};
}

// The example's median edge length: strokes a twentieth of it are visible and do not crowd.
double typicalLength(const ExampleShape& s) {
    std::vector<double> len;
    for (const ExampleEdge& e : s.edges) {
        const Point a = s.vertices[static_cast<std::size_t>(e.from)], b = s.vertices[static_cast<std::size_t>(e.to)];
        len.push_back(std::hypot(b.x - a.x, b.y - a.y));
    }
    if (len.empty()) return 1;
    std::sort(len.begin(), len.end());
    return len[len.size() / 2];
}

// The star as a person reads it: counter-clockwise from east, angles in [0°, 360°).
std::string starComment(const LabelledExample& ex, const Primitive& p) {
    std::vector<std::pair<double, int>> halves;
    for (int h : p.halves) {
        const double d = ex.direction(h);
        halves.emplace_back(d < 0 ? d + 360 : d, h);
    }
    std::sort(halves.begin(), halves.end());
    std::string out;
    for (const auto& [d, h] : halves)
        out += (out.empty() ? "E" : ", E") + std::to_string(edgeOfHalf(h)) + (barred(h) ? " in " : " out ") + num(d) + "°";
    return out;
}

std::string nodeName(int end, char prefix) { return end < 0 ? "x" + std::to_string(-1 - end) : prefix + std::to_string(end); }

// A side's own vertices and edges as statements; `prefix` names its vertices (v on the left, w on the right).
// In a match, an edge between two interface nodes is named (c0, c1, …): the
// daughter deletes it on purpose, which the name says.
void sideStatements(const RuleSide& side, char prefix, bool inMatch, std::vector<std::string>& nodes, std::vector<std::string>& edges) {
    for (std::size_t v = 0; v < side.primitive.size(); ++v)
        nodes.push_back(prefix + std::to_string(v) + ": P" + std::to_string(side.primitive[v]) + ";");
    int cut = 0;
    for (const SideEdge& e : side.edges) {
        const std::string name = inMatch && e.from < 0 && e.to < 0 ? "c" + std::to_string(cut++) + ": " : "";
        edges.push_back(name + nodeName(e.from, prefix) + " -[E" + std::to_string(e.label) + "]-> " + nodeName(e.to, prefix) + ";");
    }
}

std::string block(const std::string& keyword, const std::vector<std::string>& lines) {
    if (lines.empty()) return "    " + keyword + " { }\n";
    std::string out = "    " + keyword + " {\n";
    for (const std::string& l : lines) out += "        " + l + "\n";
    return out + "    }\n";
}

// match: `from` with the interface as wildcards; produce: the interface kept, then `to`.
// Its pieces, when `from` has several, must lie near each other (rule_pieces.hpp).
std::string dpoRule(const LabelledExample& ex, const std::string& name, const std::string& options, const RuleSide& from, char fromPrefix,
                    const RuleSide& to, char toPrefix, int interface) {
    std::vector<std::string> match, produce, edges;
    sideStatements(from, fromPrefix, true, match, edges);
    for (int k = 0; k < interface; ++k) match.push_back("x" + std::to_string(k) + ": *;");
    match.insert(match.end(), edges.begin(), edges.end());
    for (std::string& c : nearnessConditions(ex, from, to, interface)) match.push_back(std::move(c));
    for (int k = 0; k < interface; ++k) produce.push_back("x" + std::to_string(k) + ";");
    edges.clear();
    sideStatements(to, toPrefix, false, produce, edges);
    produce.insert(produce.end(), edges.begin(), edges.end());
    return "rule " + name + " dpo" + (options.empty() ? "" : " " + options) + " {\n" + block("match", match) + block("produce", produce) + "}\n";
}

// Merrell's proposal mix (the author's app: starter 1, whole-piece removal 1,
// rule 10): here per rule, so a new piece is proposed at most 1 in 12 times.
constexpr double kStarterWeight = 1, kRuleWeight = 10;
constexpr double kClearance = 0.02;   // of the example's median edge

// The example's vertices per unit area of its drawing.
double exampleDensity(const ExampleShape& s) {
    const double least = typicalLength(s);
    const auto [lo, hi] = drawingBox(s, least);
    return std::max<double>(1, static_cast<double>(s.vertices.size())) / ((hi.x - lo.x) * (hi.y - lo.y));
}

// The output's size, canvas and cost (Merrell §6.3 and Appendix A; docs/infer.md "Size and space").
std::string sizeAndSpace(const LabelledExample& ex, const WriterOptions& options) {
    const int target = options.targetVertices > 0 ? options.targetVertices : defaultTargetVertices(ex);
    const int iterations = options.iterations > 0 ? options.iterations : defaultIterations(target);
    const double least = typicalLength(ex.shape);
    const auto [lo, hi] = drawingBox(ex.shape, least);
    const double aspect = std::clamp((hi.x - lo.x) / (hi.y - lo.y), 2.0 / 3, 3.0 / 2);
    std::string out;
    out += "\n// Size and space (-D NAME=VALUE): the cost steers the walk toward target_vertices;\n"
           "// the canvas holds that many at the example's density (" + num(exampleDensity(ex.shape)) + " vertices per unit area)\n"
           "// with room to spare, unless canvas_width and canvas_height say otherwise.\n";
    out += "param target_vertices: int = " + std::to_string(target) + ";   // the example has " + std::to_string(ex.shape.vertices.size()) + "\n";
    out += "param canvas_width: float = 0;    // 0: sized for target_vertices\n";
    out += "param canvas_height: float = 0;\n";
    out += "param iterations: int = " + std::to_string(iterations) + ";\n";
    out += "const room: float = 2.25 * target_vertices / " + num(exampleDensity(ex.shape)) + ";\n";
    out += "const width: float = canvas_width > 0 ? canvas_width : sqrt(room * " + num(aspect) + ");\n";
    out += "const height: float = canvas_height > 0 ? canvas_height : sqrt(room / " + num(aspect) + ");\n";
    out += "canvas (0, 0) to (width, height);\n";
    out += "limit iterations;\n";
    out += "\n// The drawing step (Merrell §6.2) and Metropolis acceptance (§6.3): a proposal that\n"
           "// raises the cost by d is accepted with probability exp(-d / temperature). Add terms\n"
           "// to steer the output, e.g. `- 0.5 * count(P0)` for more vertices of primitive P0.\n";
    out += "layout angles {\n    cost = 0.5 * abs(nodes - target_vertices);\n    temperature = 1;\n";
    // Merrell's brush Thickness (0.05 units beside edges of 2-4): pieces keep apart by more than a stroke.
    out += "    clearance = " + num(roundSignificant(kClearance * typicalLength(ex.shape), 2)) + ";\n";
    if (options.connected) out += "    connected = true;   // no application may split the output (Appendix A)\n";
    if (options.bend) out += "    bend_segment = " + num(roundSignificant(typicalLength(ex.shape) / 25, 2)) + ";   // bent edges' segments (Appendix B)\n";
    out += "}\n";
    return out;
}

}  // namespace

int defaultTargetVertices(const LabelledExample& ex) {
    return 20 * std::max<int>(1, static_cast<int>(ex.shape.vertices.size()));
}

int defaultIterations(int targetVertices) { return std::clamp(10 * targetVertices, 1000, 1000000000); }

std::string writeGrammar(const LabelledExample& ex, const InferredGrammar& grammar, const WriterOptions& options) {
    std::string out;
    std::string source = options.source.empty() ? ex.shape.source : options.source;
    std::replace(source.begin(), source.end(), '\n', ' ');
    const int starters = grammar.starters();
    out += "// Inferred by `g2d infer` from " + source + " (Merrell 2023, example-based graph grammars).\n";
    out += "// " + std::to_string(ex.labels.size()) + " edge labels, " + std::to_string(ex.primitives.size()) + " primitives, " +
           std::to_string(static_cast<int>(grammar.rules.size()) - starters) + " rules, " + std::to_string(starters) +
           " starters" + (options.connected ? " (--connected)" : "") + ". Run: g2d run <file> -o out.svg --seed 1\n";
    out += sizeAndSpace(ex, options);

    std::set<int> areas;   // the areas some edge label has on a side
    for (const EdgeLabel& l : ex.labels)
        for (int a : {l.left, l.right})
            if (a >= 0) areas.insert(a);
    if (!areas.empty()) out += "\n// Areas of the example.\n";
    for (int a : areas)
        out += "face A" + std::to_string(a) + " { label: int = " + std::to_string(a) + "; style { fill = " + quoted(areaColour(ex, a)) +
               "; stroke = \"none\"; } }\n";

    out += "\n// Edge labels: brush, the areas left and right, the direction.\n";
    const std::string width = num(roundSignificant(0.05 * typicalLength(ex.shape), 2));
    for (std::size_t i = 0; i < ex.labels.size(); ++i) {
        const EdgeLabel& l = ex.labels[i];
        out += "edge E" + std::to_string(i) + " directed {\n    label: int = " + std::to_string(i) + ";\n";
        out += "    layout { angle = radians(" + exact(l.theta) + "); min_length = " + exact(l.minLength) + "; max_length = " + exact(l.maxLength) + ";";
        if (l.unit > 0) out += " unit = " + exact(l.unit) + ";";
        if (const double bend = ex.shape.brushes[static_cast<std::size_t>(l.brush)].bend; options.bend && bend > 0 && bend < 90)
            out += " bend = radians(" + exact(bend) + ");";
        if (l.left >= 0) out += " left = A" + std::to_string(l.left) + ";";
        if (l.right >= 0) out += " right = A" + std::to_string(l.right) + ";";
        out += " }\n    style { stroke = " + quoted(edgeColour(ex, static_cast<int>(i))) + "; stroke_width = " + width + "; }\n}\n";
    }

    out += "\n// Primitives (vertex stars): the half-edges counter-clockwise.\n";
    for (std::size_t k = 0; k < ex.primitives.size(); ++k)
        out += "node P" + std::to_string(k) + " { style { tag = \"none\"; } }   // " + starComment(ex, ex.primitives[k]) + "\n";

    out += "\naxiom { }\n";
    if (options.connected && starters > 0) out += "priority -1 limit 1;   // one starter, once\n";
    for (std::size_t r = 0; r < grammar.rules.size(); ++r) {
        const InferredRule& rule = grammar.rules[r];
        const RuleSides sides = ruleSides(ex, grammar, rule);
        const std::string i = std::to_string(r);
        if (rule.starter()) {   // L is complete: no interface, and R is nothing
            if (options.connected) {
                out += "\n// Starter " + i + ": a complete graph from nothing, once (the output is one piece).\n";
                out += dpoRule(ex, "Start" + i, "priority -1", RuleSide{}, 'w', sides.left, 'v', 0);
                continue;
            }
            out += "\n// Starter " + i + ": a complete graph from nothing, and back to nothing.\n";
            out += dpoRule(ex, "Start" + i, "weight " + num(kStarterWeight), RuleSide{}, 'w', sides.left, 'v', 0);
            out += dpoRule(ex, "Stop" + i, "weight " + num(kStarterWeight), sides.left, 'v', RuleSide{}, 'w', 0);
            continue;
        }
        const std::string boundary = boundaryString(ex, grammar.hierarchy[static_cast<std::size_t>(rule.left)].graph.boundary);
        const std::string weight = "weight " + num(kRuleWeight);
        out += "\n// Rule " + i + ": " + boundary + "\n";
        out += dpoRule(ex, "Rule" + i, weight, sides.left, 'v', sides.right, 'w', sides.interface);
        out += dpoRule(ex, "Rule" + i + "_back", weight, sides.right, 'w', sides.left, 'v', sides.interface);
    }
    return out;
}

}  // namespace g2d::infer
