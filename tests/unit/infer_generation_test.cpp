// g2d infer's grammars run (Merrell 2023 §6, issue #30): for every example,
// the written grammar compiles without a diagnostic, and its outputs for
// several seeds are planar drawings whose every vertex is a vertex of the
// example — the same labelled edges in the same directions, so the same
// areas between them — with faces on the right sides, and new shapes.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "front/compile.hpp"
#include "g2d/angle_drawing.hpp"
#include "infer/example_json.hpp"
#include "infer/example_svg.hpp"
#include "infer/grammar_writer.hpp"
#include "infer_examples.hpp"
#include "interp/run_program.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

constexpr long long kSteps = 300;

// The number after a kind's letter: P3 -> 3 (the writer's names).
int indexOf(const std::string& kindName) { return std::stoi(kindName.substr(1)); }

double degreesOf(rt::vec2 v) { return std::atan2(v.y, v.x) * 180 / M_PI; }

// [-180, 180)
double wrap(double d) {
    while (d >= 180) d -= 360;
    while (d < -180) d += 360;
    return d;
}

// A vertex's star as drawn: the directions of its edges (degrees, ascending).
using Star = std::vector<double>;

struct Output {
    std::size_t nodes = 0, faces = 0;
    std::vector<std::pair<double, double>> positions;   // sorted
    std::vector<Star> stars;                            // per node, as drawn
};

Star starOf(rt::vec2 at, const std::vector<rt::vec2>& others) {
    Star star;
    for (rt::vec2 o : others) star.push_back(degreesOf(o - at));
    std::sort(star.begin(), star.end());
    return star;
}

// Equal up to `slack` degrees, the first direction of either taken anywhere
// in the other (a direction near 180° may sort first or last).
bool sameStar(const Star& a, const Star& b, double slack) {
    if (a.size() != b.size()) return false;
    for (std::size_t r = 0; r < b.size(); ++r) {
        bool same = true;
        for (std::size_t i = 0; i < a.size() && same; ++i) same = std::abs(wrap(a[i] - b[(i + r) % b.size()])) < slack;
        if (same) return true;
    }
    return a.empty();
}

// The stars of the example as drawn (its vertices before straightening).
std::vector<Star> exampleStars(const infer::ExampleShape& shape) {
    std::vector<std::vector<rt::vec2>> ends(shape.vertices.size());
    auto at = [&](int v) { return rt::vec2{shape.vertices[static_cast<std::size_t>(v)].x, shape.vertices[static_cast<std::size_t>(v)].y}; };
    for (const infer::ExampleEdge& e : shape.edges) {
        ends[static_cast<std::size_t>(e.from)].push_back(at(e.to));
        ends[static_cast<std::size_t>(e.to)].push_back(at(e.from));
    }
    std::vector<Star> stars;
    for (std::size_t v = 0; v < shape.vertices.size(); ++v) stars.push_back(starOf(at(static_cast<int>(v)), ends[v]));
    return stars;
}

// Checks one output against the example; returns its summary.
Output checkOutput(const infer::LabelledExample& ex, const ir::Program& prog, const rt::Graph& g) {
    Output out;
    std::vector<rt::vec2> position;
    std::vector<int> vertex(g.nodeCapacity(), -1);
    for (rt::NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        vertex[n] = static_cast<int>(position.size());
        position.push_back(g.pos(n));
        out.positions.emplace_back(g.pos(n).x, g.pos(n).y);
    }
    std::sort(out.positions.begin(), out.positions.end());
    out.nodes = position.size();
    // Every edge points along its label's direction, with a length in range.
    std::vector<rt::AngleEdge> edges;
    for (rt::EdgeId e = 0; e < g.edgeCapacity(); ++e) {
        if (!g.edgeAlive(e)) continue;
        const int label = indexOf(prog.kinds[static_cast<std::size_t>(g.edgeKind(e))].name);
        const infer::EdgeLabel& l = ex.labels[static_cast<std::size_t>(label)];
        const rt::vec2 d = g.pos(g.target(e)) - g.pos(g.source(e));
        const double length = std::hypot(d.x, d.y);
        INFO("edge label " << label << " length " << length << " direction " << degreesOf(d) << " expected " << l.theta);
        CHECK(length > 1e-9);
        const double slack = 1e-9 * std::max(1.0, l.maxLength);   // the drawing step's own
        CHECK(length >= l.minLength - slack);
        CHECK(length <= l.maxLength + slack);
        CHECK(std::abs(wrap(degreesOf(d) - l.theta)) < 1e-6);
        edges.push_back(rt::AngleEdge{vertex[g.source(e)], vertex[g.target(e)], l.theta * M_PI / 180, l.minLength, l.maxLength});
    }
    CHECK(rt::drawingIsPlanar(position, edges, 1e-9));
    // Every vertex star is its primitive's: the half-edges by direction.
    for (rt::NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        std::vector<rt::vec2> others;
        for (rt::EdgeId e : g.incident(n)) others.push_back(g.pos(g.source(e) == n ? g.target(e) : g.source(e)));
        out.stars.push_back(starOf(g.pos(n), others));
        const int primitive = indexOf(prog.kinds[static_cast<std::size_t>(g.nodeKind(n))].name);
        std::vector<std::pair<double, int>> star;
        for (rt::EdgeId e : g.incident(n)) {
            const int label = indexOf(prog.kinds[static_cast<std::size_t>(g.edgeKind(e))].name);
            const bool source = g.source(e) == n;
            const double theta = ex.labels[static_cast<std::size_t>(label)].theta;
            star.emplace_back(wrap(source ? theta : theta - 180), infer::halfLabel(label, !source));
        }
        std::sort(star.begin(), star.end());
        std::vector<int> halves;
        for (const auto& s : star) halves.push_back(s.second);
        INFO("node " << n << " of primitive " << primitive);
        CHECK(halves == ex.primitives[static_cast<std::size_t>(primitive)].halves);
    }
    // Faces: counter-clockwise, each side an edge with the face's area on that side.
    for (rt::FaceId f = 0; f < g.faceCapacity(); ++f) {
        if (!g.faceAlive(f)) continue;
        ++out.faces;
        const int area = indexOf(prog.kinds[static_cast<std::size_t>(g.faceKind(f))].name);
        double twiceArea = 0;
        const rt::CornerId first = g.firstCorner(f);
        rt::CornerId c = first;
        do {
            const rt::NodeId u = g.cornerNode(c), v = g.cornerNode(g.nextCorner(c));
            twiceArea += g.pos(u).x * g.pos(v).y - g.pos(v).x * g.pos(u).y;
            int side = -2;
            for (rt::EdgeId e : g.incident(u)) {
                const int label = indexOf(prog.kinds[static_cast<std::size_t>(g.edgeKind(e))].name);
                if (g.source(e) == u && g.target(e) == v) side = ex.labels[static_cast<std::size_t>(label)].left;
                if (g.source(e) == v && g.target(e) == u) side = ex.labels[static_cast<std::size_t>(label)].right;
            }
            INFO("face " << f << " of area " << area);
            CHECK(side == area);
            c = g.nextCorner(c);
        } while (c != first);
        CHECK(twiceArea > 0);
    }
    return out;
}

// Infers, writes and compiles the grammar of `ex` (no diagnostic: g2d check
// --werror), runs it for seeds 1-3 and checks each output.
std::vector<Output> generate(const infer::LabelledExample& ex, const std::string& source) {
    const infer::InferredGrammar grammar = infer::inferGrammar(ex);
    infer::WriterOptions writer;
    writer.source = source;
    writer.iterations = static_cast<int>(kSteps);
    const std::string text = infer::writeGrammar(ex, grammar, writer);
    const CompileResult compiled = test::compile(text, "inferred.g2d");
    INFO(test::firstError(compiled));
    REQUIRE(compiled.program);
    CHECK(test::diagnosticLines(compiled).empty());
    std::vector<Output> outputs;
    for (std::uint64_t seed : {1, 2, 3}) {
        INFO("seed " << seed);
        rt::RunSettings settings;
        const interp::RunResult run = interp::runProgram(*compiled.program, interp::defaultParams(*compiled.program), seed, settings);
        CHECK(run.derivation.steps == kSteps);
        outputs.push_back(checkOutput(ex, *compiled.program, run.graph()));
    }
    return outputs;
}

bool anyDrawn(const std::vector<Output>& outputs) {
    return std::any_of(outputs.begin(), outputs.end(), [](const Output& o) { return o.nodes > 0; });
}

}  // namespace

TEST_CASE("every inferred grammar compiles cleanly and generates locally similar planar drawings", "[infer][generation]") {
    // Under the sanitizers (20 minutes otherwise), every 5th example.
    constexpr std::size_t kEvery = G2D_SANITIZED ? 5 : 1;
    int drawn = 0, tried = 0;
    const std::vector<std::string> paths = test::merrellExamplePaths();
    for (std::size_t i = 0; i < paths.size(); i += kEvery) {
        const std::string& path = paths[i];
        ++tried;
        INFO(path);
        const infer::LabelledExample ex = infer::labelExample(infer::readExampleJson(test::readFile(path), path));
        const std::vector<Output> outputs = generate(ex, std::filesystem::path(path).filename().string());
        // New shapes: the seeds' outputs differ, and none is the example.
        std::vector<std::pair<double, double>> example;
        for (const auto& v : ex.shape.vertices) example.emplace_back(v.x, v.y);
        std::sort(example.begin(), example.end());
        for (const Output& o : outputs) CHECK(o.positions != example);
        if (!anyDrawn(outputs)) continue;   // listed below
        ++drawn;
        CHECK((outputs[0].positions != outputs[1].positions || outputs[1].positions != outputs[2].positions));
    }
    // Every example: it took straightening drawn examples, unrounded rigid
    // lengths and length ranges per brush (docs/infer.md, "Generation").
    CHECK(tried == (45 + kEvery - 1) / kEvery);
    CHECK(drawn == tried);
}

TEST_CASE("a drawn example a pixel off is straightened so that its loops close", "[infer][generation]") {
    // A triangle with a centre vertex is rigid but for its size; a segment
    // from its apex, half a degree off the horizontal, joins the triangle's
    // base in one direction group. The group's direction tilts the base a quarter
    // degree, so the spokes and sides measured between the drawn vertices
    // would no longer close: no drawing of the triangle would exist.
    infer::ExampleShape shape;
    shape.source = "triangle.json";
    shape.brushes.push_back({"Line", "", false, 0, 0});
    shape.vertices = {{0, 0}, {4, 0}, {2, 3}, {2, 1}, {5, 3 + 3 * std::tan(0.5 * M_PI / 180)}};
    for (auto [a, b] : std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}, {2, 4}})
        shape.edges.push_back({a, b, 0, -1, -1, "edge"});
    shape.canvasWidth = 20;
    shape.canvasHeight = 12;
    const infer::LabelledExample ex = infer::labelExample(shape);
    CHECK(ex.snappedEdges > 0);
    CHECK(anyDrawn(generate(ex, "triangle.json")));
}

TEST_CASE("directions 8 degrees apart that the example draws exactly stay apart, and outputs have only its stars", "[infer][generation]") {
    // Two parallelograms, sides at 0° and 45°, and at 0° and 53.13° (3-4-5),
    // each slanted side drawn twice exactly. Within the 10° tolerance, yet
    // the example keeps them apart: joined at 49°, every output vertex would
    // have a star the example does not have.
    const std::string svg = R"svg(<svg xmlns="http://www.w3.org/2000/svg">
  <title>slants</title>
  <g stroke="black" fill="#d2b48c">
    <polygon points="0,0 80,0 120,-40 40,-40"/>
    <polygon points="200,0 280,0 310,-40 230,-40"/>
  </g>
</svg>
)svg";
    const infer::ExampleShape shape = infer::readExampleSvg(svg, "slants.svg");
    const infer::LabelledExample ex = infer::labelExample(shape);
    std::set<long long> directions;
    for (const infer::EdgeLabel& l : ex.labels) directions.insert(std::llround(l.theta * 100));
    CHECK(directions == std::set<long long>{0, 4500, 5313});
    const std::vector<Star> stars = exampleStars(shape);
    const std::vector<Output> outputs = generate(ex, "slants.svg");
    CHECK(anyDrawn(outputs));
    for (const Output& o : outputs)
        for (const Star& star : o.stars) {
            INFO("an output vertex with edges at " << Catch::Detail::stringify(star));
            CHECK(std::any_of(stars.begin(), stars.end(), [&](const Star& s) { return sameStar(star, s, 0.01); }));
        }
}
