// g2d infer (Merrell 2023): the example's labels and primitives, the
// boundary-string algebra (§3.3, §4.2) on the winding representation, the
// graph hierarchy and the rules of Algorithms 1 and 2.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "infer/example_json.hpp"
#include "infer_examples.hpp"
#include "infer/grammar_report.hpp"
#include "infer/matching_groups.hpp"
#include "infer/rule_application.hpp"

using namespace g2d::infer;

namespace {

using g2d::test::readFile;
const std::string kExamples = g2d::test::kMerrellExamples;
std::vector<std::pair<std::string, LabelledExample>> allExamples() { return g2d::test::merrellExamples(); }
InferOptions small() { return g2d::test::smallHierarchy(); }
LabelledExample example(const std::string& relative) { return g2d::test::merrellExample(relative); }

// A hollow 2 x 1 rectangle, corners BL, BR, TR, TL: label 0 is x (0°),
// label 1 is y (90°); halves 0 = x, 0' = x̄, 1 = y, 1' = ȳ.
LabelledExample rectangle() {
    ExampleShape s;
    s.vertices = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
    s.brushes = {{"Line", "", false, 0, 0}};
    s.source = "rectangle";
    for (int i = 0; i < 4; ++i) s.edges.push_back({i, (i + 1) % 4, 0, -1, -1, "edge " + std::to_string(i)});
    return labelExample(s);
}

// Boundary strings are cyclic: equal when one is a rotation of the other
// (each half-edge taken with the turns after it).
std::vector<std::string> groupsOf(const std::string& s) {
    std::vector<std::string> groups;
    std::istringstream in(s);
    std::string token;
    while (in >> token) {
        if ((token == "^" || token == "v") && !groups.empty()) groups.back() += " " + token;
        else groups.push_back(token);
    }
    return groups;
}
bool sameCycle(const std::string& a, const std::string& b) {
    const auto ga = groupsOf(a), gb = groupsOf(b);
    if (ga.size() != gb.size()) return false;
    for (std::size_t r = 0; r < ga.size(); ++r) {
        bool same = true;
        for (std::size_t i = 0; i < ga.size() && same; ++i) same = ga[(i + r) % ga.size()] == gb[i];
        if (same) return true;
    }
    return ga.empty();
}

int entryOf(const HierarchyGraph& g, int half) {
    for (std::size_t i = 0; i < g.boundary.size(); ++i)
        if (g.boundary[i].half == half) return static_cast<int>(i);
    FAIL("no boundary entry with that half");
    return -1;
}
int slotOf(const LabelledExample& ex, int primitive, int half) {
    const auto& h = ex.primitives[static_cast<std::size_t>(primitive)].halves;
    return static_cast<int>(std::find(h.begin(), h.end(), half) - h.begin());
}
int primitiveWith(const LabelledExample& ex, std::vector<int> halves) {
    for (std::size_t p = 0; p < ex.primitives.size(); ++p)
        if (ex.primitives[p].halves == halves) return static_cast<int>(p);
    FAIL("no such primitive");
    return -1;
}

// Every rule's sides have one boundary: the pieces' half-edges take each of
// L's once, in L's cyclic order and with L's winding differences.
void checkSplice(const InferredGrammar& g, const InferredRule& rule) {
    const auto& L = g.hierarchy[static_cast<std::size_t>(rule.left)].graph.boundary;
    const int s = static_cast<int>(L.size());
    std::vector<int> used(L.size(), 0);
    for (const RulePiece& p : rule.right) {
        const auto& R = g.hierarchy[static_cast<std::size_t>(p.graph)].graph.boundary;
        const int r = static_cast<int>(R.size());
        REQUIRE(p.leftEntry.size() == R.size());
        const int ro = static_cast<int>(std::min_element(p.leftEntry.begin(), p.leftEntry.end()) - p.leftEntry.begin());
        for (int k = 0; k < r; ++k) {
            const int q = (ro + k) % r;
            const int l = p.leftEntry[static_cast<std::size_t>(q)];
            ++used[static_cast<std::size_t>(l)];
            CHECK(L[static_cast<std::size_t>(l)].half == R[static_cast<std::size_t>(q)].half);
            if (k > 0) CHECK(l > p.leftEntry[static_cast<std::size_t>((ro + k - 1) % r)]);
            const int windR = R[static_cast<std::size_t>(q)].wind + (ro + k) / r - R[static_cast<std::size_t>(ro)].wind;
            const int windL = L[static_cast<std::size_t>(l)].wind - L[static_cast<std::size_t>(p.leftEntry[static_cast<std::size_t>(ro)])].wind;
            CHECK(windL == windR);
        }
    }
    for (int u : used) CHECK(u == (rule.starter() ? 0 : 1));
    (void)s;
}

}  // namespace

TEST_CASE("a rectangle's corners are the primitives xy^, x'y^, y'x^, x'y'^", "[infer]") {
    const LabelledExample ex = rectangle();
    REQUIRE(ex.labels.size() == 2);
    CHECK(ex.labels[0].theta == 0);
    CHECK(ex.labels[1].theta == 90);
    REQUIRE(ex.primitives.size() == 4);
    CHECK(ex.primitives[0].halves == std::vector<int>{0, 2});   // BL: x, y
    CHECK(ex.primitives[1].halves == std::vector<int>{1, 2});   // BR: x', y
    CHECK(ex.primitives[2].halves == std::vector<int>{1, 3});   // TR: x', y'
    CHECK(ex.primitives[3].halves == std::vector<int>{3, 0});   // TL: y', x
    CHECK(boundaryString(ex, primitiveGraph(ex, 0).boundary) == "0 1 ^");
    CHECK(boundaryString(ex, primitiveGraph(ex, 3).boundary) == "1' 0 ^");
}

TEST_CASE("gluing the rectangle's corners follows the string rules of §4.2", "[infer]") {
    const LabelledExample ex = rectangle();
    const int BL = primitiveWith(ex, {0, 2}), BR = primitiveWith(ex, {1, 2}), TR = primitiveWith(ex, {1, 3}), TL = primitiveWith(ex, {3, 0});
    // BR's x' glued to BL: x'y^ -> y^y (the bottom side, two upward half-edges).
    const HierarchyGraph bottom = branchGlue(ex, primitiveGraph(ex, BR), entryOf(primitiveGraph(ex, BR), 1), BL, slotOf(ex, BL, 0));
    CHECK(sameCycle(boundaryString(ex, bottom.boundary), "1 ^ 1"));
    // BL's y glued to TL: x^y.
    const HierarchyGraph left = branchGlue(ex, bottom, entryOf(bottom, 2) == 0 ? 0 : 0, TL, slotOf(ex, TL, 3));
    // (whichever y the entry is, the string is x^y or y^x'-like; check the one on BL's side below)
    const HierarchyGraph three = branchGlue(ex, bottom, [&] {
        for (std::size_t i = 0; i < bottom.boundary.size(); ++i)
            if (bottom.type[static_cast<std::size_t>(bottom.boundary[i].vertex)] == BL) return static_cast<int>(i);
        return -1;
    }(), TL, slotOf(ex, TL, 3));
    CHECK(sameCycle(boundaryString(ex, three.boundary), "0 ^ 1"));
    // The last corner, TR, on the remaining y: x ^ ^ x' v; loop glue x' v x ^ -> nothing: complete.
    const HierarchyGraph open = branchGlue(ex, three, entryOf(three, 2), TR, slotOf(ex, TR, 3));
    CHECK(sameCycle(boundaryString(ex, open.boundary), "0 ^ ^ 0' v"));
    HierarchyGraph closed;
    bool glued = false;
    for (int i = 0; i < 2 && !glued; ++i) glued = loopGlue(ex, open, i, closed);
    REQUIRE(glued);
    CHECK(closed.complete());
    CHECK(closed.gluedEdges() == 4);
    // Open at the bottom instead: TL + TR, then BL, then BR: x x' ^, and x x' -> nothing.
    const HierarchyGraph top = branchGlue(ex, primitiveGraph(ex, TL), entryOf(primitiveGraph(ex, TL), 0), TR, slotOf(ex, TR, 1));
    CHECK(sameCycle(boundaryString(ex, top.boundary), "1' 1' ^"));
    (void)left;
}

TEST_CASE("an edge graph is a^a', and a straight vertex has the same boundary", "[infer]") {
    ExampleShape s;
    s.vertices = {{0, 0}, {1, 0}, {3, 0}};
    s.brushes = {{"Line", "", false, 0, 0}};
    s.edges = {{0, 1, 0, -1, -1, "a"}, {1, 2, 0, -1, -1, "b"}};
    const LabelledExample ex = labelExample(s);
    const HierarchyGraph edge = edgeGraph(ex, 0);
    CHECK(boundaryString(ex, edge.boundary) == "0 ^ 0'");
    const int middle = primitiveWith(ex, {1, 0});
    CHECK(boundaryString(ex, primitiveGraph(ex, middle).boundary) == "0' 0 ^");
    CHECK(sameCycle(boundaryString(ex, primitiveGraph(ex, middle).boundary), boundaryString(ex, edge.boundary)));
    // Algorithm 2 reduces the straight vertex to the edge.
    std::vector<GroupEntry> S;
    const auto& B = primitiveGraph(ex, middle).boundary;
    for (std::size_t i = 0; i < B.size(); ++i) S.push_back({B[i].half, B[i].wind, static_cast<int>(i)});
    HierarchyEntry e;
    e.graph = edge;
    e.halves = {0, 1};
    e.halfMask = 3;
    std::vector<RulePiece> pieces;
    REQUIRE(findMatchingGroups(S, {&e}, {7}, pieces));
    REQUIRE(pieces.size() == 1);
    CHECK(pieces[0].graph == 7);
}

TEST_CASE("the §5.3 group example: abcdefghi^ against acg^ leaves b, def and hi", "[infer]") {
    // Nine labels, one half each; candidates acg^, b^, def^ and hi^ made as boundaries directly.
    auto graph = [](std::vector<int> halves) {
        HierarchyEntry e;
        for (std::size_t i = 0; i < halves.size(); ++i) e.graph.boundary.push_back({halves[i], 0, static_cast<int>(i), 0});
        e.graph.type = {0};
        e.halves = halves;
        std::sort(e.halves.begin(), e.halves.end());
        for (int h : halves) e.halfMask |= std::uint64_t{1} << h;
        return e;
    };
    std::vector<GroupEntry> S;
    for (int i = 0; i < 9; ++i) S.push_back({2 * i, 0, i});
    const HierarchyEntry acg = graph({0, 4, 12}), b = graph({2}), def = graph({6, 8, 10}), hi = graph({14, 16});
    std::vector<RulePiece> pieces;
    REQUIRE(findMatchingGroups(S, {&acg, &def, &hi, &b}, {0, 1, 2, 3}, pieces));
    REQUIRE(pieces.size() == 4);
    CHECK(pieces[0].graph == 0);
    CHECK(pieces[0].leftEntry == std::vector<int>{0, 2, 6});
    // Without hi^ there is no grouping.
    REQUIRE_FALSE(findMatchingGroups(S, {&acg, &def, &b}, {0, 1, 3}, pieces));
    // A winding that disagrees: c turned once more in S than in acg^.
    S[2].wind = 1;
    for (std::size_t i = 3; i < S.size(); ++i) S[i].wind = 1;
    REQUIRE_FALSE(findMatchingGroups(S, {&acg, &def, &hi, &b}, {0, 1, 2, 3}, pieces));
}

TEST_CASE("the same graph glued in two orders has one canonical code, and occurs in itself", "[infer]") {
    const LabelledExample ex = rectangle();
    const int BL = primitiveWith(ex, {0, 2}), BR = primitiveWith(ex, {1, 2});
    const HierarchyGraph a = branchGlue(ex, primitiveGraph(ex, BR), entryOf(primitiveGraph(ex, BR), 1), BL, slotOf(ex, BL, 0));
    const HierarchyGraph b = branchGlue(ex, primitiveGraph(ex, BL), entryOf(primitiveGraph(ex, BL), 0), BR, slotOf(ex, BR, 1));
    CHECK(canonicalCode(a) == canonicalCode(b));
    CHECK(canonicalCode(a) != canonicalCode(primitiveGraph(ex, BL)));
    CHECK(occursIn(primitiveGraph(ex, BL), a));
    CHECK(occursIn(a, b));
    CHECK_FALSE(occursIn(a, primitiveGraph(ex, BL)));
}

TEST_CASE("labels and primitives of the author's 45 examples", "[infer][examples]") {
    // (labels, primitives). Four differ from docs/research/merrell-digest.md §7.3, whose
    // script neither joined directions across 0°/180° (house hollow, 3-way horizontal,
    // hexagons) nor kept rigid edges of different lengths apart (diagonal complex).
    const std::map<std::string, std::pair<int, int>> expected = {
        {"2D Basic Shapes/L", {4, 5}}, {"2D Basic Shapes/diagonal box", {3, 4}}, {"2D Basic Shapes/diagonal complex", {8, 12}},
        {"2D Basic Shapes/diagonal row", {6, 6}}, {"2D Basic Shapes/house hollow", {4, 5}}, {"2D Basic Shapes/square filled", {4, 4}},
        {"2D Basic Shapes/square hollow", {2, 4}}, {"2D Basic Shapes/star crossing", {3, 9}}, {"2D Basic Shapes/star hollow", {4, 12}},
        {"2D Basic Shapes/triangle complex", {6, 9}}, {"2D Basic Shapes/triangle square", {4, 7}}, {"2D Basic Shapes/triangle", {3, 3}},
        {"2D Branches/A", {3, 5}}, {"2D Branches/H", {2, 4}}, {"2D Branches/T", {2, 4}}, {"2D Branches/U", {2, 3}},
        {"2D Branches/Z", {2, 4}}, {"2D Branches/angle", {2, 3}}, {"2D Branches/branches", {3, 5}}, {"2D Branches/curl", {2, 6}},
        {"2D Branches/h complex", {4, 8}}, {"2D Branches/intersection", {2, 6}}, {"2D Branches/line", {1, 2}},
        {"2D Branches/plus", {2, 5}}, {"2D Branches/right angles", {2, 4}}, {"2D Networks/2-colored boxes", {4, 6}},
        {"2D Networks/3-way horizontal", {2, 6}}, {"2D Networks/4-way filled", {4, 6}}, {"2D Networks/4-way hollow", {2, 5}},
        {"2D Networks/connected box", {6, 8}}, {"2D Networks/connected triangle", {6, 4}}, {"2D Networks/divided box", {6, 10}},
        {"2D Networks/overlapping boxes", {8, 12}}, {"2D Regions/framed box filled", {4, 12}},
        {"2D Regions/framed box hollow", {12, 8}}, {"2D Regions/hexagons", {10, 13}}, {"2D Regions/koch snowflake", {12, 18}},
        {"2D Regions/pass through grid", {6, 9}}, {"2D Regions/simple stack", {9, 10}}, {"2D Regions/slanted stack", {10, 11}},
        {"2D Regions/spaceships", {13, 13}}, {"2D Regions/stacked platform", {8, 8}}, {"2D Regions/super k", {18, 18}},
        {"2D Regions/windows", {7, 7}}, {"2D Regions/x-cross", {6, 9}},
    };
    int files = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kExamples)) {
        if (entry.path().extension() != ".json") continue;
        ++files;
        const std::string key = entry.path().parent_path().filename().string() + "/" + entry.path().stem().string();
        INFO(key);
        REQUIRE(expected.count(key) == 1);
        const LabelledExample ex = labelExample(readExampleJson(readFile(entry.path().string()), key));
        CHECK(static_cast<int>(ex.labels.size()) == expected.at(key).first);
        CHECK(static_cast<int>(ex.primitives.size()) == expected.at(key).second);
    }
    CHECK(files == 45);
}

namespace {

// Separate segments from (x, y) in direction `degrees`, `length` long (example units).
LabelledExample segments(const std::vector<std::tuple<double, double, double, double>>& drawn) {
    ExampleShape s;
    s.source = "segments";
    s.brushes = {{"Line", "", false, 0, 0}};
    for (const auto& [x, y, degrees, length] : drawn) {
        const int v = static_cast<int>(s.vertices.size());
        s.vertices.push_back({x, y});
        s.vertices.push_back({x + length * std::cos(degrees * M_PI / 180), y + length * std::sin(degrees * M_PI / 180)});
        s.edges.push_back({v, v + 1, 0, -1, -1, "edge " + std::to_string(v / 2)});
    }
    return labelExample(s);
}

std::set<long long> directionsOf(const LabelledExample& ex) {   // hundredths of a degree
    std::set<long long> out;
    for (const EdgeLabel& l : ex.labels) out.insert(std::llround(l.theta * 100));
    return out;
}

}  // namespace

TEST_CASE("the angle tolerance joins drawing noise, never directions the example tells apart", "[infer]") {
    // A single edge 5° off joins the direction: noise.
    CHECK(directionsOf(segments({{0, 0, 0, 2}, {0, 1, 0, 2}, {0, 2, 5, 2}})).size() == 1);
    // Each drawn exactly twice, 8° apart: two directions.
    CHECK(directionsOf(segments({{0, 0, 45, 2}, {3, 0, 45, 2}, {6, 0, 53, 2}, {9, 0, 53, 2}})) == std::set<long long>{4500, 5300});
    // ... but not when a pixel at the end of their edges (1/40 unit over 2
    // units: 0.72° each) could make the difference.
    CHECK(directionsOf(segments({{0, 0, 0, 2}, {0, 1, 0, 2}, {0, 2, 0.3, 2}, {0, 3, 0.3, 2}})).size() == 1);
    // Two edges leaving one vertex 8° apart would lie on one ray: two
    // directions, where one was an error ("two edges in one direction").
    ExampleShape wedge;
    wedge.source = "wedge";
    wedge.brushes = {{"Line", "", false, 0, 0}};
    wedge.vertices = {{0, 0}, {2 * std::cos(M_PI / 4), 2 * std::sin(M_PI / 4)}, {2 * std::cos(53 * M_PI / 180), 2 * std::sin(53 * M_PI / 180)}};
    wedge.edges = {{0, 1, 0, -1, -1, "edge 0"}, {0, 2, 0, -1, -1, "edge 1"}};
    const LabelledExample ex = labelExample(wedge);
    CHECK(directionsOf(ex) == std::set<long long>{4500, 5300});
    CHECK(ex.primitives.size() == 3);
}

TEST_CASE("the triangle needs one starter rule and nothing else, as the author's tool finds", "[infer][examples]") {
    const LabelledExample ex = example("2D Basic Shapes/triangle.json");
    const InferredGrammar g = inferGrammar(ex);
    CHECK(g.starters() == 1);
    CHECK(g.rules.size() == 1);
    CHECK(g.leftOver() == 0);
    const HierarchyGraph& triangle = g.hierarchy[static_cast<std::size_t>(g.rules[0].left)].graph;
    CHECK(triangle.vertexCount() == 3);
    CHECK(triangle.gluedEdges() == 3);
}

TEST_CASE("every example's grammar starts, and every rule joins sides with one boundary string", "[infer][examples]") {
    for (const auto& [path, ex] : allExamples()) {
        INFO(path);
        const InferredGrammar g = inferGrammar(ex, small());
        // Whatever the limits, the example itself is reducible: the grammar can start.
        CHECK(g.starters() >= 1);
        for (const InferredRule& rule : g.rules) {
            checkSplice(g, rule);
            // The right side is simpler: fewer half-edges, or as many and found earlier.
            for (const RulePiece& p : rule.right) {
                const auto& R = g.hierarchy[static_cast<std::size_t>(p.graph)];
                const auto& L = g.hierarchy[static_cast<std::size_t>(rule.left)];
                CHECK((R.graph.boundary.size() < L.graph.boundary.size() ||
                       (R.graph.boundary.size() == L.graph.boundary.size() && R.order < L.order)));
            }
        }
    }
}

// Whether the grammar takes graph g to nothing: a starter deletes it, or some
// rule, applied destructively at its first match, leaves parts it takes to
// nothing (depth-first over every rule; a graph met again on the way is a loop).
bool reducesToNothing(const LabelledExample& ex, const InferredGrammar& g, const HierarchyGraph& graph, std::set<std::string>& path,
                      int depth = 0) {
    const std::string code = canonicalCode(graph);
    for (const InferredRule& r : g.rules)
        if (r.starter() && canonicalCode(g.hierarchy[static_cast<std::size_t>(r.left)].graph) == code) return true;
    if (depth > 60 || !path.insert(code).second) return false;
    bool done = false;
    for (std::size_t i = 0; i < g.rules.size() && !done; ++i) {
        const InferredRule& rule = g.rules[i];
        if (rule.starter()) continue;
        const std::vector<int> image = findOccurrence(g.hierarchy[static_cast<std::size_t>(rule.left)].graph, graph);
        if (image.empty()) continue;
        done = true;
        for (const HierarchyGraph& part : applyDestructively(ex, g, rule, graph, image))
            done = done && reducesToNothing(ex, g, part, path, depth + 1);
    }
    path.erase(code);
    return done;
}

TEST_CASE("every example's grammar takes the example to nothing (so it can make it)", "[infer][examples]") {
    for (const auto& [path, ex] : allExamples()) {
        INFO(path);
        const InferredGrammar g = inferGrammar(ex, small());
        // The example as one hierarchy graph per component: a grammar run on the example's own vertices.
        HierarchyGraph whole;
        for (std::size_t v = 0; v < ex.vertexType.size(); ++v) {
            whole.type.push_back(ex.vertexType[v]);
            whole.links.emplace_back(ex.primitives[static_cast<std::size_t>(ex.vertexType[v])].halves.size());
        }
        for (std::size_t e = 0; e < ex.shape.edges.size(); ++e) {
            const ExampleEdge& edge = ex.shape.edges[e];
            const bool flipped = ex.edgeFlipped[e] != 0;
            const auto slot = [&](int v, int half) {
                const auto& h = ex.primitives[static_cast<std::size_t>(ex.vertexType[static_cast<std::size_t>(v)])].halves;
                return static_cast<int>(std::find(h.begin(), h.end(), half) - h.begin());
            };
            const int a = slot(edge.from, halfLabel(ex.edgeLabel[e], flipped)), b = slot(edge.to, halfLabel(ex.edgeLabel[e], !flipped));
            whole.links[static_cast<std::size_t>(edge.from)][static_cast<std::size_t>(a)] = {edge.to, b};
            whole.links[static_cast<std::size_t>(edge.to)][static_cast<std::size_t>(b)] = {edge.from, a};
        }
        for (const HierarchyGraph& component : components(ex, whole)) {
            std::set<std::string> path;
            CHECK(reducesToNothing(ex, g, component, path));
        }
    }
}

TEST_CASE("a tree's grammar has both stubs of every label, and no graph left over (§5.5)", "[infer][examples]") {
    for (const char* name : {"2D Branches/T.json", "2D Branches/H.json", "2D Branches/plus.json", "2D Branches/curl.json",
                             "2D Branches/h complex.json", "2D Branches/right angles.json"}) {
        INFO(name);
        const LabelledExample ex = example(name);
        const InferredGrammar g = inferGrammar(ex);
        CHECK(g.leftOver() == 0);
        CHECK(g.starters() >= 1);
        for (std::size_t l = 0; l < ex.labels.size(); ++l)
            for (int bar = 0; bar < 2; ++bar) {
                const int half = halfLabel(static_cast<int>(l), bar != 0);
                bool stub = false;
                for (const HierarchyEntry& h : g.hierarchy)
                    stub = stub || (h.state == GraphState::Active && h.graph.boundary.size() == 1 && h.graph.boundary[0].half == half);
                CHECK(stub);
            }
    }
}

TEST_CASE("inference is deterministic", "[infer][examples]") {
    // Against a listing kept in the repository (a run in another process, on
    // another build): a result that depended on addresses, uninitialised
    // memory or the order of a hash would differ from it. After a deliberate
    // change to inference, G2D_UPDATE_GOLDEN=1 writes it again.
    const LabelledExample ex = example("2D Networks/connected box.json");
    const std::string listing = describeGrammar(ex, inferGrammar(ex));
    CHECK(listing == describeGrammar(ex, inferGrammar(ex)));
    const std::string golden = G2D_SOURCE_DIR "/tests/unit/golden/connected_box_grammar.txt";
    if (std::getenv("G2D_UPDATE_GOLDEN")) std::ofstream(golden, std::ios::binary) << listing;
    std::ifstream in(golden, std::ios::binary);
    REQUIRE(in);
    std::stringstream kept;
    kept << in.rdbuf();
    CHECK(listing == kept.str());
}

TEST_CASE("bad examples are refused with the place of the fault", "[infer][errors]") {
    auto error = [](const std::string& text) {
        try {
            labelExample(readExampleJson(text, "x.json"));
        } catch (const InputError& e) {
            return e.message;
        }
        return std::string("no error");
    };
    CHECK(error("[1, 1") == "x.json:1:6: not valid JSON: syntax error while parsing array - unexpected end of input; expected ']'");
    CHECK(error("[1, 11e3081]") == "x.json:1:5: not valid JSON: the number 11e3081 is out of range");
    CHECK(error("[7]") == "x.json: data[0]: format version 7 is not 1 to 5");
    CHECK(error("[1, 1, \"0,0,10,0\", \"\", \"0,5,-1,-1\", 1, 0, 0, 0, false]") ==
          "x.json: data[4]: edge 0 names a vertex that does not exist");
    CHECK(error("[1, 1, \"0,0,80,0,40,-40,40,40\", \"\", \"0,1,-1,-1,2,3,-1,-1\", 1, 0, 0, 0, false]") ==
          "x.json: data[4], edge 0: the edge crosses data[4], edge 1; an example must be a plane drawing");
    CHECK(error("[1, 1, \"0,0,80,0,40,0\", \"\", \"0,1,-1,-1\", 1, 0, 0, 0, false]") ==
          "x.json: data[2], vertex 2: the vertex at (1, 0) has no edges");
    // Version 3: one brush, one area; the triangle's first edge has the area on its
    // left, the others on their right: at two corners the wedge is both.
    CHECK(error("[3, 1, false, true, true, true, 10, \"#000\", \"#000\", 1, \"#fff\", \"#000\", 1, "
                "\"0,0,80,0,40,-40\", \"\", \"0,1,-1,-1,1,2,-1,-1,2,0,-1,-1\", \"0,0,0\", \"0,-1,-1,0,-1,0\", "
                "1, 0, 0, 0, 0, false]") ==
          "x.json: the areas around the vertex at (0, 0) disagree: between its edges at 0° and 45° one says Area0, the other no area");
    CHECK(error("[1, 1, \"0,0,80,0\", \"\", \"0,1,-1,-1\", 1, 0, 0, 0, false, 3]") ==
          "x.json: data[10]: unexpected data after the last instance");
}

TEST_CASE("§5.6: spirals of rectangle corners are pruned, and a rectangle's grammar has one starter rule", "[infer]") {
    const LabelledExample ex = rectangle();
    const InferredGrammar g = inferGrammar(ex);
    CHECK(g.leftOver() == 0);
    // Every complete graph of rectangle corners is a rectangle: one starter rule,
    // and the rules that make the corners' graphs of equal boundaries one.
    CHECK(g.starters() == 1);
    std::vector<std::string> pruned;
    for (const HierarchyEntry& h : g.hierarchy)
        if (h.state == GraphState::Pruned) pruned.push_back(boundaryString(ex, h.graph.boundary));
    const auto found = [&](const std::string& s) {
        return std::any_of(pruned.begin(), pruned.end(), [&](const std::string& p) { return sameCycle(p, s); });
    };
    // The spiral family starts where a boundary path first turns more than 360°
    // (y^(n+1) y' v^n needs n >= 2; the paper's y^4 y' v^3 lies further on):
    // x^^y'v (450°), and its mirror images and clockwise twins, are pruned,
    // and nothing grows from them.
    INFO([&] { std::string all; for (const auto& p : pruned) all += p + " | "; return all; }());
    CHECK(pruned.size() == 4);
    CHECK(found("0 ^ ^ 1' v"));
    CHECK(found("1 ^ ^ 0 v"));
    CHECK(found("1 0' ^"));
    CHECK(found("0' v 1' ^ ^"));
    for (const HierarchyEntry& h : g.hierarchy)
        if (h.state == GraphState::Active) CHECK_FALSE(h.graph.boundary.size() > 4);
}
