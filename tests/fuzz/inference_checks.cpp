// The structured inference target: the bytes describe a plane straight-line
// drawing (vertices on a small grid, edges added where they cross nothing,
// edge labels, an area label per bounded face), which g2d infer must either
// refuse with a located reason or turn into a grammar that compiles without
// a diagnostic and whose outputs are locally similar to the drawing.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "byte_source.hpp"
#include "driver/big_stack.hpp"
#include "front/compile.hpp"
#include "fuzz_checks.hpp"
#include "g2d/run_driver.hpp"
#include "inferred_output.hpp"
#include "infer/grammar_inference.hpp"
#include "infer/grammar_writer.hpp"
#include "infer/labelled_example.hpp"
#include "interp/interpreted_run.hpp"
#include "reader_checks.hpp"

namespace g2d::fuzz {

namespace {

struct GridPoint {
    long long x, y;
};

long long cross(GridPoint o, GridPoint a, GridPoint b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool onSegment(GridPoint p, GridPoint a, GridPoint b) {
    return cross(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

// Do segments ab and cd share a point other than a common end?
bool meet(const std::vector<GridPoint>& p, int a, int b, int c, int d) {
    const int shared = (a == c) + (a == d) + (b == c) + (b == d);
    if (shared == 1) {   // only collinear overlap beyond the shared end
        const int v = (a == c || a == d) ? a : b;
        const int x = v == a ? b : a, y = (c == v) ? d : c;
        return cross(p[v], p[x], p[y]) == 0 && (onSegment(p[y], p[v], p[x]) || onSegment(p[x], p[v], p[y]));
    }
    const long long d1 = cross(p[a], p[b], p[c]), d2 = cross(p[a], p[b], p[d]);
    const long long d3 = cross(p[c], p[d], p[a]), d4 = cross(p[c], p[d], p[b]);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    return onSegment(p[c], p[a], p[b]) || onSegment(p[d], p[a], p[b]) || onSegment(p[a], p[c], p[d]) || onSegment(p[b], p[c], p[d]);
}

// Faces of the drawing: for each directed edge (index 2e: from -> to, 2e+1:
// back), the face on its left, and each face's twice-signed area.
void traceFaces(const std::vector<GridPoint>& p, const std::vector<std::pair<int, int>>& edges, std::vector<int>& faceOf,
                std::vector<long long>& twiceArea) {
    const int nh = 2 * static_cast<int>(edges.size());
    auto tail = [&](int h) { return h % 2 == 0 ? edges[h / 2].first : edges[h / 2].second; };
    auto head = [&](int h) { return tail(h ^ 1); };
    std::map<int, std::vector<int>> out;   // vertex -> outgoing half-edges, counter-clockwise
    for (int h = 0; h < nh; ++h) out[tail(h)].push_back(h);
    for (auto& [vertex, hs] : out) {
        const GridPoint o = p[vertex];
        std::sort(hs.begin(), hs.end(), [&](int a, int b) {
            const GridPoint pa = p[head(a)], pb = p[head(b)];
            return std::atan2(double(pa.y - o.y), double(pa.x - o.x)) < std::atan2(double(pb.y - o.y), double(pb.x - o.x));
        });
    }
    // Keeping the face on the left: at the head, the outgoing edge just clockwise of the way back.
    auto next = [&](int h) {
        const auto& hs = out[head(h)];
        const auto at = std::find(hs.begin(), hs.end(), h ^ 1) - hs.begin();
        return hs[(static_cast<std::size_t>(at) + hs.size() - 1) % hs.size()];
    };
    faceOf.assign(static_cast<std::size_t>(nh), -1);
    for (int h0 = 0; h0 < nh; ++h0) {
        if (faceOf[h0] >= 0) continue;
        const int face = static_cast<int>(twiceArea.size());
        long long area = 0;
        for (int h = h0; faceOf[h] < 0; h = next(h)) {
            faceOf[h] = face;
            area += p[tail(h)].x * p[head(h)].y - p[head(h)].x * p[tail(h)].y;
        }
        twiceArea.push_back(area);
    }
}

infer::ExampleShape drawingOf(ByteSource& in) {
    infer::ExampleShape shape;
    shape.source = "drawing.json";
    const int n = 3 + static_cast<int>(in.below(8));
    std::vector<GridPoint> p;
    for (int i = 0; i < 3 * n && static_cast<int>(p.size()) < n; ++i) {
        const GridPoint q{in.below(8), in.below(8)};
        if (std::none_of(p.begin(), p.end(), [&](GridPoint r) { return r.x == q.x && r.y == q.y; })) p.push_back(q);
    }
    std::vector<std::pair<int, int>> edges;
    const int nv = static_cast<int>(p.size());
    for (int i = 0; i < 3 * nv; ++i) {
        const int a = static_cast<int>(in.below(nv)), b = static_cast<int>(in.below(nv));
        if (a == b) continue;
        bool free = true;
        for (int v = 0; v < nv && free; ++v) free = v == a || v == b || !onSegment(p[v], p[a], p[b]);
        for (const auto& [c, d] : edges) free = free && !((c == a && d == b) || (c == b && d == a)) && !meet(p, a, b, c, d);
        if (free) edges.emplace_back(a, b);
    }
    const int brushes = 1 + static_cast<int>(in.below(3)), areas = static_cast<int>(in.below(3));
    for (int b = 0; b < brushes; ++b) {
        infer::EdgeBrush brush{"Line" + std::to_string(b), "", false, 0, 0};
        brush.rigid = in.below(4) == 0;
        shape.brushes.push_back(brush);
    }
    for (int a = 0; a < areas; ++a) shape.areas.push_back({"Area" + std::to_string(a), ""});
    std::vector<int> faceOf;
    std::vector<long long> twiceArea;
    traceFaces(p, edges, faceOf, twiceArea);
    std::vector<int> faceLabel(twiceArea.size(), -1);
    for (std::size_t f = 0; f < twiceArea.size(); ++f)
        if (twiceArea[f] > 0 && areas > 0) faceLabel[f] = static_cast<int>(in.below(areas + 1)) - 1;
    // A vertex no edge touches is kept only sometimes: the reader refuses it.
    const bool keepIsolated = in.below(8) == 0;
    std::vector<int> index(static_cast<std::size_t>(nv), -1);
    for (int v = 0; v < nv; ++v) {
        const bool used = std::any_of(edges.begin(), edges.end(), [&](const auto& e) { return e.first == v || e.second == v; });
        if (!used && !keepIsolated) continue;
        index[static_cast<std::size_t>(v)] = static_cast<int>(shape.vertices.size());
        shape.vertices.push_back({static_cast<double>(p[v].x), static_cast<double>(p[v].y)});
        shape.vertexWhere.push_back("vertex " + std::to_string(v));
    }
    for (std::size_t e = 0; e < edges.size(); ++e) {
        infer::ExampleEdge edge;
        edge.from = index[static_cast<std::size_t>(edges[e].first)];
        edge.to = index[static_cast<std::size_t>(edges[e].second)];
        edge.brush = static_cast<int>(in.below(brushes));
        edge.leftArea = faceLabel[static_cast<std::size_t>(faceOf[2 * e])];
        edge.rightArea = faceLabel[static_cast<std::size_t>(faceOf[2 * e + 1])];
        edge.where = "edge " + std::to_string(e);
        shape.edges.push_back(edge);
    }
    shape.canvasWidth = shape.canvasHeight = 40;
    return shape;
}

void checkInferenceHere(const std::uint8_t* data, std::size_t size) {
    ByteSource in(data, size);
    const infer::ExampleShape shape = drawingOf(in);
    if (shape.edges.empty()) return;
    infer::LabelledExample ex;
    try {
        ex = infer::labelExample(shape);
    } catch (const infer::InputError& e) {
        if (e.message.rfind(shape.source + ":", 0) != 0) violated("a refusal that does not say where: " + e.message);
        return;
    }
    infer::InferOptions options;
    options.maxGraphs = 400;
    const infer::InferredGrammar grammar = infer::inferGrammar(ex, options);
    infer::WriterOptions writer;
    writer.source = shape.source;
    writer.iterations = 120;
    writer.connected = in.below(2) == 1;
    const std::string source = infer::writeGrammar(ex, grammar, writer);
    const CompileResult compiled = compileSource("/nonexistent-g2d-fuzz/inferred.g2d", source, LoadOptions{});
    checkDiagnostics(compiled);
    for (const auto& d : compiled.diags.sorted())
        violated("the inferred grammar has a diagnostic: " + std::to_string(d.span.line) + ": " + d.message);
    interp::InterpretedRun run(*compiled.program, &compiled.sources);
    rt::RunSettings settings;
    settings.maxElements = 20000;
    settings.timeoutSeconds = 5.0;
    try {
        std::vector<rt::Value> params;
        for (const auto& p : run.params()) params.push_back(p.defaultValue);
        rt::DerivedRun derived;
        rt::deriveGrammar(run, params, 1 + in.below(1000), settings, derived);
    } catch (const std::exception& e) {
        if (auto wrong = unexpectedRunFailure(e, run)) violated("in the derivation: " + *wrong);
    }
    const InferredOutput output = measureInferredOutput(ex, *compiled.program, run.graph());
    if (output.dissimilar >= 0) violated("node " + std::to_string(output.dissimilar) + "'s star is not its primitive's");
    if (writer.connected && output.pieces > 1) violated("a --connected output in " + std::to_string(output.pieces) + " pieces");
}

}  // namespace

void checkInferenceOnDrawing(const std::uint8_t* data, std::size_t size) {
    runWithBigStack([&] {
        try {
            checkInferenceHere(data, size);
        } catch (const infer::InputError& e) {
            violated("inference refused a labelled drawing: " + e.message);
        } catch (const std::exception& e) {
            violated(std::string("inference threw: ") + e.what());
        }
        return 0;
    });
}

}  // namespace g2d::fuzz
