#include "infer/grammar_writer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

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

// Areas without a colour of their own: light, distinct, and the same for the same index every time.
const char* const kPalette[] = {"#a6cee3", "#b2df8a", "#fb9a99", "#fdbf6f", "#cab2d6", "#ffff99", "#8dd3c7", "#bebada"};

std::string areaColour(const LabelledExample& ex, int a) {
    const std::string& own = ex.shape.areas[static_cast<std::size_t>(a)].color;
    return own.empty() ? kPalette[static_cast<std::size_t>(a) % std::size(kPalette)] : own;
}

// The canvas: the example's own extents centred on its drawing, else its bounding box grown by half on each side.
std::pair<Point, Point> canvas(const ExampleShape& s) {
    Point lo{1e300, 1e300}, hi{-1e300, -1e300};
    for (const Point& p : s.vertices) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    const Point mid{(lo.x + hi.x) / 2, (lo.y + hi.y) / 2};
    double w = hi.x - lo.x, h = hi.y - lo.y;
    if (s.canvasWidth > 0 && s.canvasHeight > 0) {
        w = s.canvasWidth;
        h = s.canvasHeight;
    } else {
        // A flat example (one straight line) still needs room across it.
        const double w0 = w > 0 ? w : h, h0 = h > 0 ? h : w;
        w = 2 * w0;
        h = 2 * h0;
    }
    return {{mid.x - w / 2, mid.y - h / 2}, {mid.x + w / 2, mid.y + h / 2}};
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
std::string dpoRule(const std::string& name, const RuleSide& from, char fromPrefix, const RuleSide& to, char toPrefix, int interface) {
    std::vector<std::string> match, produce, edges;
    sideStatements(from, fromPrefix, true, match, edges);
    for (int k = 0; k < interface; ++k) match.push_back("x" + std::to_string(k) + ": *;");
    match.insert(match.end(), edges.begin(), edges.end());
    for (int k = 0; k < interface; ++k) produce.push_back("x" + std::to_string(k) + ";");
    edges.clear();
    sideStatements(to, toPrefix, false, produce, edges);
    produce.insert(produce.end(), edges.begin(), edges.end());
    return "rule " + name + " dpo {\n" + block("match", match) + block("produce", produce) + "}\n";
}

}  // namespace

std::string writeGrammar(const LabelledExample& ex, const InferredGrammar& grammar, const WriterOptions& options) {
    std::string out;
    std::string source = options.source.empty() ? ex.shape.source : options.source;
    std::replace(source.begin(), source.end(), '\n', ' ');
    const int starters = grammar.starters();
    out += "// Inferred by `g2d infer` from " + source + " (Merrell 2023, example-based graph grammars).\n";
    out += "// " + std::to_string(ex.labels.size()) + " edge labels, " + std::to_string(ex.primitives.size()) + " primitives, " +
           std::to_string(static_cast<int>(grammar.rules.size()) - starters) + " rules, " + std::to_string(starters) +
           " starters. Run: g2d run <file> -o out.svg --seed 1\n";
    const auto [lo, hi] = canvas(ex.shape);
    out += "layout angles {\n    canvas_min = (" + num(lo.x) + ", " + num(lo.y) + ");\n    canvas_max = (" + num(hi.x) + ", " + num(hi.y) +
           ");\n}\n";
    out += "param iterations: int = " + std::to_string(options.iterations) + ";\nlimit iterations;\n";

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
        const std::string& colour = ex.shape.brushes[static_cast<std::size_t>(l.brush)].color;
        out += "edge E" + std::to_string(i) + " directed {\n    label: int = " + std::to_string(i) + ";\n";
        out += "    layout { angle = radians(" + exact(l.theta) + "); min_length = " + exact(l.minLength) + "; max_length = " + exact(l.maxLength) + ";";
        if (l.left >= 0) out += " left = A" + std::to_string(l.left) + ";";
        if (l.right >= 0) out += " right = A" + std::to_string(l.right) + ";";
        out += " }\n    style { stroke = " + quoted(colour.empty() ? "#202020" : colour) + "; stroke_width = " + width + "; }\n}\n";
    }

    out += "\n// Primitives (vertex stars): the half-edges counter-clockwise.\n";
    for (std::size_t k = 0; k < ex.primitives.size(); ++k)
        out += "node P" + std::to_string(k) + " { style { tag = \"none\"; } }   // " + starComment(ex, ex.primitives[k]) + "\n";

    out += "\naxiom { }\n";
    for (std::size_t r = 0; r < grammar.rules.size(); ++r) {
        const InferredRule& rule = grammar.rules[r];
        const RuleSides sides = ruleSides(ex, grammar, rule);
        const std::string i = std::to_string(r);
        if (rule.starter()) {   // L is complete: no interface, and R is nothing
            out += "\n// Starter " + i + ": a complete graph from nothing, and back to nothing.\n";
            out += dpoRule("Start" + i, RuleSide{}, 'w', sides.left, 'v', 0);
            out += dpoRule("Stop" + i, sides.left, 'v', RuleSide{}, 'w', 0);
            continue;
        }
        out += "\n// Rule " + i + ": " +
               boundaryString(ex, grammar.hierarchy[static_cast<std::size_t>(rule.left)].graph.boundary) + "\n";
        out += dpoRule("Rule" + i, sides.left, 'v', sides.right, 'w', sides.interface);
        out += dpoRule("Rule" + i + "_back", sides.right, 'w', sides.left, 'v', sides.interface);
    }
    return out;
}

}  // namespace g2d::infer
