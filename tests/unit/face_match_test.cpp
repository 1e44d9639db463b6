// Face patterns against a brute-force matcher: random graphs of faces of two
// kinds and three or four corners (overlapping, sharing sides either way),
// and random face patterns (corners of any kind or wildcards, faces of any
// corner count, two faces sharing a side or a corner, conditions on faces
// and corners). The brute force tries every assignment of pattern faces to
// host faces and of rotations, and knows nothing of search plans or the
// corner lists at nodes. A derivation then rewrites faces at random with
// match verification on (test::verified()), so repair is checked too.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <set>
#include <sstream>

#include "interp/interpreted_rules.hpp"
#include "interp/run_program.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

struct HostFace {
    int kind, value;          // kind 0: F, 1: G
    std::vector<int> corners;
};
struct PatFace {
    int kind;
    std::vector<int> corners; // pattern nodes; empty: any corner count
    int minValue = -1;        // where f.v > minValue (-1: no condition)
    bool big = false;         // where f.area > 2
    bool lonely = false;      // where f.neighbours == 0
};
struct Case {
    std::vector<int> hostKind, hostValue;   // kind 0: A, 1: B
    std::vector<HostFace> hostFaces;
    std::vector<int> patKind;               // -1: wildcard
    std::vector<PatFace> patFaces;
    int nodeCond = -1, nodeCondMin = 0;     // where p[nodeCond].v > nodeCondMin (typed nodes only)
    // A negative condition: 1: no face of kind nacKind with v < 3 on (p1, p0, z)
    // with z an A node outside the match; 2: no face of kind nacKind with v > 2.
    int nac = 0, nacKind = 0;
};

const char* nodeKind(int k) { return k == 0 ? "A" : k == 1 ? "B" : "*"; }
const char* faceKind(int k) { return k == 0 ? "F" : "G"; }

std::string source(const Case& c) {
    std::ostringstream s;
    s << "node A { v: int = 0; } node B { v: int = 0; } edge E;\nface F { v: int = 0; } face G { v: int = 0; }\naxiom {\n";
    for (std::size_t i = 0; i < c.hostKind.size(); ++i)
        s << "  h" << i << ": " << nodeKind(c.hostKind[i]) << " at (" << i << ", " << (i * i) % 5 << ") { v = " << c.hostValue[i] << " };\n";
    for (const auto& f : c.hostFaces) {
        s << "  " << faceKind(f.kind) << "(";
        for (std::size_t j = 0; j < f.corners.size(); ++j) s << (j ? ", " : "") << "h" << f.corners[j];
        s << ") { v = " << f.value << " };\n";
    }
    s << "}\nlimit 0;\nrule R {\n  match {\n";
    for (std::size_t i = 0; i < c.patKind.size(); ++i) s << "    p" << i << ": " << nodeKind(c.patKind[i]) << ";\n";
    for (std::size_t i = 0; i < c.patFaces.size(); ++i) {
        const auto& f = c.patFaces[i];
        s << "    f" << i << ": " << faceKind(f.kind);
        if (!f.corners.empty()) {
            s << "(";
            for (std::size_t j = 0; j < f.corners.size(); ++j) s << (j ? ", " : "") << "p" << f.corners[j];
            s << ")";
        }
        std::string where;
        if (f.minValue >= 0) where += " and f" + std::to_string(i) + ".v > " + std::to_string(f.minValue);
        if (f.big) where += " and f" + std::to_string(i) + ".area > 2";
        if (f.lonely) where += " and f" + std::to_string(i) + ".neighbours == 0";
        if (!where.empty()) s << " where" << where.substr(4);
        s << ";\n";
    }
    if (c.nodeCond >= 0) s << "    where p" << c.nodeCond << ".v > " << c.nodeCondMin << ";\n";
    if (c.nac == 1) s << "    not { z: A; g: " << faceKind(c.nacKind) << "(p1, p0, z) where g.v < 3; }\n";
    if (c.nac == 2) s << "    not { g: " << faceKind(c.nacKind) << " where g.v > 2; }\n";
    s << "  }\n  produce {";
    for (std::size_t i = 0; i < c.patKind.size(); ++i) s << " p" << i << ";";
    for (std::size_t i = 0; i < c.patFaces.size(); ++i) s << " f" << i << ";";
    s << " }\n}\n";
    return s.str();
}

double area(const Case& c, const HostFace& f) {   // positions as source() writes them
    double twice = 0;
    for (std::size_t i = 0; i < f.corners.size(); ++i) {
        const double a = f.corners[i], b = f.corners[(i + 1) % f.corners.size()];
        twice += a * ((b * b) - 5 * std::floor(b * b / 5)) - b * ((a * a) - 5 * std::floor(a * a / 5));
    }
    (void)c;
    return std::abs(twice) / 2;
}

int neighbours(const Case& c, int face) {
    const auto& f = c.hostFaces[static_cast<std::size_t>(face)].corners;
    int count = 0;
    for (int o = 0; o < static_cast<int>(c.hostFaces.size()); ++o) {
        if (o == face) continue;
        const auto& g = c.hostFaces[static_cast<std::size_t>(o)].corners;
        bool shares = false;
        for (std::size_t i = 0; i < f.size(); ++i)
            for (std::size_t j = 0; j < g.size(); ++j) {
                const int a = f[i], b = f[(i + 1) % f.size()], x = g[j], y = g[(j + 1) % g.size()];
                shares = shares || (a == x && b == y) || (a == y && b == x);
            }
        count += shares;
    }
    return count;
}

// Every match as (pattern nodes..., hidden anchors..., faces...), by brute force.
std::set<std::vector<std::uint32_t>> bruteForce(const Case& c) {
    std::set<std::vector<std::uint32_t>> out;
    const std::size_t pn = c.patKind.size(), pf = c.patFaces.size();
    std::vector<int> faces(pf, -1), start(pf, 0);
    std::function<void(std::size_t)> bindFace = [&](std::size_t i) {
        if (i == pf) {
            std::vector<int> nodes(pn, -1);
            for (std::size_t k = 0; k < pf; ++k) {
                const auto& hc = c.hostFaces[static_cast<std::size_t>(faces[k])].corners;
                const auto& pc = c.patFaces[k].corners;
                for (std::size_t j = 0; j < pc.size(); ++j) {
                    const int h = hc[(static_cast<std::size_t>(start[k]) + j) % hc.size()];
                    int& n = nodes[static_cast<std::size_t>(pc[j])];
                    if (n >= 0 && n != h) return;
                    n = h;
                }
            }
            for (std::size_t p = 0; p < pn; ++p) {
                const int h = nodes[p];
                if (h < 0) return;   // the generator puts every pattern node on a face
                if (c.patKind[p] >= 0 && c.hostKind[static_cast<std::size_t>(h)] != c.patKind[p]) return;
                for (std::size_t q = 0; q < p; ++q)
                    if (nodes[q] == h) return;
            }
            if (c.nodeCond >= 0 && !(c.hostValue[static_cast<std::size_t>(nodes[static_cast<std::size_t>(c.nodeCond)])] > c.nodeCondMin)) return;
            for (int h = 0; h < static_cast<int>(c.hostFaces.size()) && c.nac; ++h) {
                const auto& hf = c.hostFaces[static_cast<std::size_t>(h)];
                if (hf.kind != c.nacKind || std::find(faces.begin(), faces.end(), h) != faces.end()) continue;
                if (c.nac == 2 && hf.value > 2) return;
                if (c.nac != 1 || hf.corners.size() != 3 || !(hf.value < 3)) continue;
                for (std::size_t r = 0; r < 3; ++r) {
                    const int z = hf.corners[(r + 2) % 3];
                    if (hf.corners[r] == nodes[1] && hf.corners[(r + 1) % 3] == nodes[0] && c.hostKind[static_cast<std::size_t>(z)] == 0 &&
                        std::find(nodes.begin(), nodes.end(), z) == nodes.end())
                        return;
                }
            }
            std::vector<std::uint32_t> m(nodes.begin(), nodes.end());
            for (std::size_t k = 0; k < pf; ++k)
                if (c.patFaces[k].corners.empty()) m.push_back(static_cast<std::uint32_t>(c.hostFaces[static_cast<std::size_t>(faces[k])].corners[0]));
            for (int f : faces) m.push_back(static_cast<std::uint32_t>(f));
            out.insert(m);
            return;
        }
        const auto& p = c.patFaces[i];
        for (int f = 0; f < static_cast<int>(c.hostFaces.size()); ++f) {
            const auto& h = c.hostFaces[static_cast<std::size_t>(f)];
            if (h.kind != p.kind || std::find(faces.begin(), faces.begin() + static_cast<long>(i), f) != faces.begin() + static_cast<long>(i)) continue;
            if (!p.corners.empty() && p.corners.size() != h.corners.size()) continue;
            if (p.minValue >= 0 && !(h.value > p.minValue)) continue;
            if (p.big && !(area(c, h) > 2)) continue;
            if (p.lonely && neighbours(c, f) != 0) continue;
            faces[i] = f;
            const int rotations = p.corners.empty() ? 1 : static_cast<int>(h.corners.size());
            for (int r = 0; r < rotations; ++r) {
                start[i] = r;
                bindFace(i + 1);
            }
            faces[i] = -1;
        }
    };
    bindFace(0);
    return out;
}

Case randomCase(std::mt19937& gen) {
    auto pick = [&](int n) { return static_cast<int>(gen() % static_cast<unsigned>(n)); };
    Case c;
    const int hn = 5 + pick(4);
    for (int i = 0; i < hn; ++i) {
        c.hostKind.push_back(pick(2));
        c.hostValue.push_back(pick(4));
    }
    // Faces on random distinct corners, and some sharing a side (either way).
    const int hf = 2 + pick(6);
    for (int i = 0; i < hf; ++i) {
        std::vector<int> nodes(static_cast<std::size_t>(hn));
        for (int n = 0; n < hn; ++n) nodes[static_cast<std::size_t>(n)] = n;
        std::shuffle(nodes.begin(), nodes.end(), gen);
        nodes.resize(static_cast<std::size_t>(3 + pick(2)));
        if (i > 0 && pick(2)) {   // share a side of an earlier face
            const auto& other = c.hostFaces[static_cast<std::size_t>(pick(i))].corners;
            const int j = pick(static_cast<int>(other.size()));
            int a = other[static_cast<std::size_t>(j)], b = other[static_cast<std::size_t>(j + 1) % other.size()];
            if (pick(2)) std::swap(a, b);
            nodes.erase(std::remove_if(nodes.begin(), nodes.end(), [&](int n) { return n == a || n == b; }), nodes.end());
            while (nodes.size() < 1) nodes.push_back(-1);
            std::vector<int> corners{a, b};
            for (int n : nodes)
                if (n >= 0 && corners.size() < 4) corners.push_back(n);
            if (corners.size() < 3) continue;
            nodes = corners;
        }
        c.hostFaces.push_back({pick(2), pick(4), nodes});
    }
    auto kind = [&] {
        const int k = pick(5);
        return k < 2 ? k : k == 2 ? -1 : pick(2);
    };
    switch (pick(4)) {
    case 0: {   // one face with its corners
        const int k = 3 + pick(2);
        for (int i = 0; i < k; ++i) c.patKind.push_back(kind());
        PatFace f{pick(2), {}};
        for (int i = 0; i < k; ++i) f.corners.push_back(i);
        c.patFaces.push_back(f);
        break;
    }
    case 1:   // a face of any corner count
        c.patFaces.push_back({pick(2), {}});
        break;
    case 2: {   // two faces sharing a side, either way
        for (int i = 0; i < 4; ++i) c.patKind.push_back(kind());
        c.patFaces.push_back({pick(2), {0, 1, 2}});
        c.patFaces.push_back(pick(2) ? PatFace{pick(2), {1, 0, 3}} : PatFace{pick(2), {0, 1, 3}});
        break;
    }
    default:   // a face with corners and a face of any count
        for (int i = 0; i < 3; ++i) c.patKind.push_back(kind());
        c.patFaces.push_back({pick(2), {0, 1, 2}});
        c.patFaces.push_back({pick(2), {}});
        break;
    }
    for (auto& f : c.patFaces) {
        if (pick(3) == 0) f.minValue = pick(3);
        f.big = pick(4) == 0;
        f.lonely = pick(5) == 0;
    }
    if (pick(3) == 0) {
        c.nac = c.patKind.size() >= 2 && pick(2) ? 1 : 2;
        c.nacKind = pick(2);
    }
    for (std::size_t i = 0; i < c.patKind.size(); ++i)
        if (c.patKind[i] >= 0 && pick(4) == 0) {
            c.nodeCond = static_cast<int>(i);
            c.nodeCondMin = pick(3);
        }
    return c;
}

}  // namespace

TEST_CASE("face patterns find exactly the matches a brute-force matcher finds", "[match][brute][faces]") {
    std::mt19937 gen(20261201);
    int nonEmpty = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const Case c = randomCase(gen);
        const std::string text = source(c);
        INFO(text);
        auto compiled = test::compile(text);
        REQUIRE(compiled.program);
        const auto& prog = *compiled.program;
        const auto& rule = prog.rules[0];
        const int nn = static_cast<int>(rule.nodes.size()), nf = static_cast<int>(rule.faces.size());
        rt::Rng rng(1);
        auto [st, g] = test::startInterpreter(prog, rng);
        interp::InterpretedRules rules(st);
        rt::MatchBuffer found;
        found.reset(nn, 0, nf);
        rules.findMatches(0, g, found);
        std::set<std::vector<std::uint32_t>> engine;
        const std::size_t width = static_cast<std::size_t>(nn + nf);
        for (std::size_t i = 0; i < found.size(); ++i) engine.emplace(found.ids(i), found.ids(i) + width);
        CHECK(engine.size() == found.size());   // no match twice
        const auto expected = bruteForce(c);
        CHECK(engine == expected);
        // Every anchored search finds exactly the matches binding its anchor
        // (its caller tests the anchor's kind: rt::RepairArea::searchesAt).
        for (int p = 0; p < nn; ++p)
            for (std::uint32_t h = 0; h < c.hostKind.size(); ++h) {
                if (rule.nodes[static_cast<std::size_t>(p)].kind >= 0 && static_cast<int>(g.nodeKind(h)) != rule.nodes[static_cast<std::size_t>(p)].kind)
                    continue;
                found.reset(nn, 0, nf);
                rules.findAnchored(0, g, p, h, found);
                std::set<std::vector<std::uint32_t>> anchored, wanted;
                for (std::size_t i = 0; i < found.size(); ++i) anchored.emplace(found.ids(i), found.ids(i) + width);
                for (const auto& m : expected)
                    if (m[static_cast<std::size_t>(p)] == h) wanted.insert(m);
                CHECK(anchored == wanted);
            }
        nonEmpty += !expected.empty();
    }
    CHECK(nonEmpty > 60);   // the generator makes patterns that do match
}

TEST_CASE("incrementally kept face matches equal a full search after every random rewrite", "[match][incremental][faces]") {
    // The random pattern's rule, and rules that delete, create, re-value and
    // move faces and their corners; the derivation checks every rule's set
    // against a full search after every step (test::verified()).
    std::mt19937 gen(11);
    long long steps = 0;
    for (int trial = 0; trial < 80; ++trial) {
        const Case c = randomCase(gen);
        std::string text = source(c);
        text.replace(text.find("limit 0;"), 8, "limit 30;");
        const auto produce = text.find("  produce {");
        std::string daughter = "  produce {";
        // Keep the nodes (moving the first when it has a kind), keep the first
        // face with a new value, delete the others.
        for (std::size_t i = 0; i < c.patKind.size(); ++i)
            daughter += i == 0 && c.patKind[0] >= 0 ? " p0 at p0.pos + (0.5, 0.25);" : " p" + std::to_string(i) + ";";
        daughter += " f0 { v = f0.v + 1 };";
        daughter += " }\n}\n";
        daughter += "rule Grow { match { a: A; b: B; not { x: A; a -[E]- x; } } produce { a; b; n: A at (a.pos + b.pos) / 2; "
                    "a -[E]- n; F(a, b, n) { v = 2 }; } }\n";
        daughter += "rule Drop { match { g: G where g.v < 2; } produce { } }\n";
        daughter += "rule Move { match { x: A where x.v < 3; } produce { x at x.pos + (0.5, 0.25) { v = x.v + 1 }; } }\n";
        daughter += "rule Kill { match { x: B where x.v == 3; g: F(x, y, z); y: *; z: *; } produce { y; z; } }\n";
        text = text.substr(0, produce) + daughter;
        INFO(text);
        auto compiled = test::compile(text);
        REQUIRE(compiled.program);
        auto run = interp::runProgram(*compiled.program, interp::defaultParams(*compiled.program), 1 + trial, test::verified());
        CHECK(run.derivation.steps <= 30);
        steps += run.derivation.steps;
    }
    CHECK(steps > 400);   // the rules do rewrite
}

TEST_CASE("a negative condition's face whose first corner lies outside the match is watched through its corners",
          "[match][incremental][faces]") {
    // g's first corner is z, which no edge joins to the match: when Bump
    // writes g.v, only z is marked, and repair must reach p0 and p1 through
    // g's corners (lower::repairRadius counts a face as joining them).
    const std::string text = R"(
node A;
node M;
face F { v: int = 0; }
face T;
axiom {
    a: A at (0, 0); b: A at (1, 0); q: A at (0.5, 1); z: A at (0.5, -1);
    T(a, b, q);
    F(z, b, a);
}
rule R priority 1 {
    match { t: T(p0, p1, q); p0: A; p1: A; q: A; not { z: A; g: F(p1, p0, z) where g.v < 1; } }
    produce { t; p0; p1; q; m: M at t.centroid; }
}
rule Bump priority 0 {
    match { g: F where g.v < 1; }
    produce { g { v = 1 }; }
}
)";
    auto compiled = test::compile(text);
    REQUIRE(compiled.program);
    auto run = interp::runProgram(*compiled.program, interp::defaultParams(*compiled.program), 1, test::verified(5));
    CHECK(run.derivation.steps == 5);   // Bump, then R on every step (it keeps its match)
}

TEST_CASE("a face matched by its first corner loses its match when a neighbour comes on another side",
          "[match][incremental][faces]") {
    // f's first corner is a; Add's triangle shares f's side b-c only, so
    // only f's neighbour count tells Lonely that f is no longer alone.
    const std::string text = R"(
node A;
face F;
face T;
axiom { a: A at (0, 0); b: A at (1, 0); c: A at (0, 1); d: A at (1, 1); F(a, b, c); }
rule Add {
    match { b: A where b.id == 1; c: A where c.id == 2; d: A where d.id == 3; not { t: T; } }
    produce { b; c; d; T(c, b, d); }
}
rule Lonely priority 1 {
    match { f: F where f.neighbours == 0; }
    produce { f; m: A at f.centroid; }
}
)";
    auto compiled = test::compile(text);
    REQUIRE(compiled.program);
    auto run = interp::runProgram(*compiled.program, interp::defaultParams(*compiled.program), 1, test::verified(5));
    CHECK(run.derivation.steps == 1);   // Add; then f has a neighbour and nothing matches
}

TEST_CASE("signed_area tells a clockwise face from a counter-clockwise one", "[match][faces]") {
    const std::string text = R"(
node A;
face F;
axiom { a: A at (0, 0); b: A at (2, 0); c: A at (0, 1); F(a, b, c); F(a, c, b); }
limit 0;
rule Clockwise { match { f: F where f.signed_area < 0 and f.area == -f.signed_area; } produce { f; } }
)";
    auto compiled = test::compile(text);
    REQUIRE(compiled.program);
    rt::Rng rng(1);
    auto [st, g] = test::startInterpreter(*compiled.program, rng);
    interp::InterpretedRules rules(st);
    rt::MatchBuffer found;
    found.reset(1, 0, 1);
    rules.findMatches(0, g, found);
    REQUIRE(found.size() == 1);
    CHECK(found[0].faces[0] == 1);   // F(a, c, b), of area -1
    CHECK(g.signedArea(1) == -1.0);
}
