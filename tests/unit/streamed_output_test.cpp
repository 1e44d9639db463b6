// Outputs written in pieces (TextOut, AtomicFile) are the bytes written
// whole: the streamed SVG (items made one at a time, ordered by compact keys)
// equals the SVG of all items at hand, numbers print as formatNumber, and a
// file appears only on commit.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <unistd.h>

#include "g2d/atomic_file.hpp"
#include "g2d/json_writer.hpp"
#include "g2d/projection.hpp"
#include "g2d/svg_writer.hpp"
#include "g2d/text_out.hpp"
#include "interp/run_program.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

test::SnippetRun runExample(const std::string& name, long long steps) {
    rt::RunSettings settings;
    settings.steps = steps;
    return test::runSnippet(readFile(std::string(G2D_SOURCE_DIR) + "/examples/" + name), 1, settings);
}

// The SVG as the driver streams it, and as written from all items at once.
std::pair<std::string, std::string> bothSvgs(rt::GrammarRun& run, const rt::SvgOptions& options = {}) {
    const rt::Graph& g = run.graph();
    const bool space3d = run.jsonSchema().space3d;
    const rt::ViewProjection view = rt::viewFrom(rt::kDefaultViewFrom);
    std::vector<rt::DrawItem> items = run.drawItems();
    if (space3d) rt::projectDrawing(items, g, view);
    const std::string whole = rt::writeSvg(std::move(items), run.svgDefs(), options);
    rt::StringOut out;
    const rt::SolidFaces solid(g);
    rt::writeSvg(g, [&](rt::ElemClass cls, std::uint32_t id, rt::DrawItem& it) {
        run.drawItem(cls, id, it);
        if (space3d) rt::projectItem(it, g, view, solid);
    }, run.svgDefs(), out, options);
    return {out.text(), whole};
}

}  // namespace

TEST_CASE("the streamed SVG equals the SVG of all items at once", "[output][svg]") {
    // 2D edges and nodes, faces, z orders, 3D depth order.
    for (const auto& [name, steps] : std::vector<std::pair<std::string, long long>>{
             {"koch_snowflake.g2d", 60}, {"tree.g2d", 120}, {"subdivide.g2d", 40}, {"floor_plan.g2d", 50},
             {"stained_glass.g2d", 60}, {"g3_box.g2d", 60}, {"g3_house.g2d", 80}}) {
        INFO(name);
        auto r = runExample(name, steps);
        const auto [streamed, whole] = bothSvgs(*r.grammar);
        CHECK(streamed.size() > 200);
        CHECK(streamed == whole);
        rt::SvgOptions compact;
        compact.compact = true;
        compact.precision = 2;
        const auto [streamedCompact, wholeCompact] = bothSvgs(*r.grammar, compact);
        CHECK(streamedCompact == wholeCompact);
    }
}

TEST_CASE("z values out of the graph's order are sorted without holding items", "[output][svg]") {
    // Later nodes are drawn first: the order leaves the graph's own at the second node.
    auto c = test::compile("node V { style { z = 10 - id; r = 0.2; } }\nedge E { style { z = 3; } }\n"
                           "axiom { a: V at (0, 0); b: V at (1, 0); d: V at (2, 1); a -[E]- b; b -[E]- d; }\n");
    INFO(test::firstError(c));
    REQUIRE(c.program);
    auto r = interp::runProgram(*c.program, {}, 1, rt::RunSettings{});
    const auto [streamed, whole] = bothSvgs(*r.grammar);
    CHECK(streamed == whole);
    CHECK(streamed.find("<line") < streamed.find("cx=\"2\""));
    CHECK(streamed.find("cx=\"2\"") < streamed.find("cx=\"0\""));
}

TEST_CASE("numbers print as formatNumber, digit for digit", "[output]") {
    std::mt19937_64 gen(7);
    std::vector<double> xs = {0.0, -0.0, 1.0, -1.0, 0.1, 1e-300, -2.5e300, 1e21, 123456789.125, 5e-324,
                              std::nan(""), INFINITY, -INFINITY, 0.30000000000000004};
    std::uniform_real_distribution<double> unit(-1, 1);
    for (int i = 0; i < 2000; ++i) xs.push_back(unit(gen) * std::pow(10.0, static_cast<int>(gen() % 40) - 20));
    rt::StringOut out;
    std::string want;
    for (double x : xs) {
        out.number(x);
        out.write(' ');
        want += rt::formatNumber(x) + " ";
    }
    out.integer(-9223372036854775807LL);
    want += "-9223372036854775807";
    CHECK(out.text() == want);
}

TEST_CASE("a text longer than the buffer arrives whole and in order", "[output]") {
    rt::StringOut out;
    std::string want;
    for (int i = 0; i < 100000; ++i) {
        const std::string piece = std::to_string(i) + (i % 1000 == 0 ? std::string(70000, 'x') : ",");
        out.write(piece);
        want += piece;
    }
    CHECK(out.text() == want);
}

TEST_CASE("an AtomicFile written in pieces appears only on commit", "[output][atomic]") {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("g2d-streamed-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string path = (dir / "out.txt").string();
    std::string want;
    {
        rt::AtomicFile file(path);
        for (int i = 0; i < 50000; ++i) {
            const std::string piece = "line " + std::to_string(i) + "\n";
            file.write(piece);
            want += piece;
        }
        CHECK_FALSE(fs::exists(path));   // not before commit
        file.commit();
    }
    CHECK(readFile(path) == want);
    {
        rt::AtomicFile file(path);
        file.write(std::string(1 << 20, 'y'));
        // Destroyed without commit (an error while writing): the old file stays.
    }
    CHECK(readFile(path) == want);
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);   // no temporary left
    fs::remove_all(dir);
}

TEST_CASE("staged commits appear when their group is placed, a failed placement is reported and cleaned up",
          "[output][atomic]") {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("g2d-staged-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string a = (dir / "a.svg").string(), b = (dir / "b.svg").string();
    std::vector<rt::StagedFile> staged;
    rt::setCommitStaging(&staged);
    for (const auto& path : {a, b}) {
        rt::AtomicFile file(path);
        file.write("text of " + path);
        file.commit();
    }
    rt::setCommitStaging(nullptr);
    REQUIRE(staged.size() == 2);
    CHECK_FALSE(fs::exists(a));   // written, not in place
    CHECK(fs::exists(staged[0].temp));
    CHECK(staged[1].path == b);
    rt::releaseStaged(staged);
    // b's name is taken by a folder meanwhile: its placement fails, a's does not.
    fs::create_directories(dir / "b.svg" / "inside");
    const std::vector<std::string> errors = rt::placeStaged(staged);
    CHECK(errors[0].empty());
    CHECK(readFile(a) == "text of " + a);
    CHECK_THAT(errors[1], Catch::StartsWith("cannot write `" + b + "`: "));
    CHECK_FALSE(fs::exists(staged[1].temp));   // no temporary left
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 2);   // a.svg, b.svg/
    // Without a staging list, commits are in place at once again.
    {
        rt::AtomicFile file(a);
        file.write("again");
        file.commit();
    }
    CHECK(readFile(a) == "again");
    fs::remove_all(dir);
}

TEST_CASE("JSON multigraph keys count parallel edges per source and target", "[output][json]") {
    auto c = test::compile("node V; edge E directed;\n"
                           "axiom { a: V at (0, 0); b: V at (1, 0); a -[E]-> b; a -[E]-> b; b -[E]-> a; a -[E]-> b; }\n");
    REQUIRE(c.program);
    auto r = interp::runProgram(*c.program, {}, 1, rt::RunSettings{});
    const std::string json = rt::writeJson(r.graph(), r.grammar->jsonSchema(), {});
    CHECK_THAT(json, Catch::Contains("\"key\": 0, \"id\": 0") && Catch::Contains("\"key\": 1, \"id\": 1") &&
                         Catch::Contains("\"key\": 0, \"id\": 2") && Catch::Contains("\"key\": 2, \"id\": 3"));
}
