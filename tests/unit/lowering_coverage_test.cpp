// Every operation of the lowered programs occurs in some example: an
// operation no grammar reaches is one the differential tests never check.
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>

#include "front/compile.hpp"
#include "lower/match_program.hpp"
#include "lower/rewrite_program.hpp"
#include "lower/start_program.hpp"
#include "test_helpers.hpp"

using namespace g2d;

TEST_CASE("every lowered operation occurs in the examples", "[lower]") {
    std::set<std::size_t> prepare, commit, match;
    int grammars = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(G2D_SOURCE_DIR) + "/examples")) {
        if (entry.path().extension() != ".g2d") continue;
        LoadOptions options;
        options.importDirs = {G2D_STDLIB_DIR};
        auto c = compileFile(entry.path().string(), options);
        INFO(entry.path().string());
        REQUIRE(c.program);
        ++grammars;
        // The axiom's rewrite (faces are created there only, for now).
        for (const auto& op : lower::lowerStart(*c.program).axiom.commit) commit.insert(op.index());
        for (const auto& r : c.program->rules) {
            for (std::size_t d = 0; d < r.daughters.size(); ++d) {
                const auto p = lower::lowerRewrite(*c.program, r, d);
                for (const auto& op : p.prepare) prepare.insert(op.index());
                for (const auto& op : p.commit) commit.insert(op.index());
            }
            const auto m = lower::lowerMatch(*c.program, r);
            auto note = [&](const lower::MatchList& l) {
                for (const auto& op : l) match.insert(op.index());
            };
            note(m.full);
            for (const auto& l : m.anchored) note(l);
            for (const auto& l : m.negatives) note(l);
        }
    }
    CHECK(grammars >= 10);
    CHECK(prepare.size() == std::variant_size_v<lower::PrepareOp>);
    CHECK(commit.size() == std::variant_size_v<lower::CommitOp>);
    CHECK(match.size() == std::variant_size_v<lower::MatchOp>);
}
