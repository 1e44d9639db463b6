#pragma once
// What the run-semantics tests share: a grammar's whole interpreted run, with
// incremental matching verified after every step, and small lookups.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "interp/run_program.hpp"
#include "test_helpers.hpp"

namespace g2d::test {


struct Run {
    CompileResult compiled;
    interp::RunResult run;
};

// Incremental matching is verified after every step unless `verify` is off
// (for derivations too long to search in full at each step).
inline Run derive(const std::string& source, std::uint64_t seed = 1, std::optional<long long> steps = {},
           std::vector<std::pair<std::string, rt::Value>> params = {}, bool verify = true) {
    Run r{compile(source), {}};
    INFO(test::firstError(r.compiled));
    REQUIRE(r.compiled.program);
    const auto& prog = *r.compiled.program;
    auto values = interp::defaultParams(prog);
    for (const auto& [name, v] : params)
        for (std::size_t i = 0; i < prog.params.size(); ++i)
            if (prog.params[i].name == name) values[i] = v;
    rt::RunSettings settings = test::verified(steps);
    settings.verifyMatches = verify;
    r.run = interp::runProgram(prog, values, seed, settings);
    return r;
}

inline std::size_t countNodes(const rt::Graph& g, int kind) { return g.nodesOfKind(kind).size(); }

inline int kindIndex(const ir::Program& p, const std::string& name) {
    for (std::size_t i = 0; i < p.kinds.size(); ++i)
        if (p.kinds[i].name == name) return static_cast<int>(i);
    return -1;
}

inline std::string koch() {
    std::ifstream in(std::string(G2D_SOURCE_DIR) + "/examples/koch_snowflake.g2d");
    return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace g2d::test
