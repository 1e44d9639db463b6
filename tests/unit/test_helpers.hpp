#pragma once
// Compiling snippets in tests, and reading their diagnostics.
#include <memory>
#include <string>
#include <vector>

#include "front/compile.hpp"
#include "g2d/graph.hpp"
#include "g2d/rng.hpp"
#include "g2d/run_driver.hpp"
#include "interp/program_state.hpp"
#include "interp/run_program.hpp"

namespace g2d::test {

// Compiles `text` as if it were the file `name` in tests/unit (imports
// resolve against the real stdlib).
CompileResult compile(const std::string& text, const std::string& name = "snippet.g2d");

// "LINE:COL: error: MESSAGE" for each diagnostic, sorted by position.
std::vector<std::string> diagnosticLines(const CompileResult& r);
// The first error as "LINE:COL: MESSAGE", or "" if there is none.
std::string firstError(const CompileResult& r);

// A small valid grammar to build test cases from: kinds P (node, attribute
// w: float), E (directed edge, attribute n: int), U (undirected edge).
std::string prelude();

// The interpreter's state for `prog` (default parameters) and its axiom
// graph, for tests that drive the runtime themselves.
struct InterpreterStart {
    interp::ProgramState state;
    rt::Graph graph;
};
InterpreterStart startInterpreter(const ir::Program& prog, rt::Rng& rng);

// Run settings for tests: after every step, every rule's kept matches are
// checked against a full search (a std::logic_error on a difference).
rt::RunSettings verified(std::optional<long long> steps = {});

// An interpreted run of a snippet together with its program: the run points
// into the program, so the program is a base listed first (destroyed last).
struct KeptProgram {
    std::unique_ptr<CompileResult> compiled;
};
struct SnippetRun : KeptProgram, interp::RunResult {};
// Compiles `text` (throws with its first error) and runs it with default
// parameters.
SnippetRun runSnippet(const std::string& text, std::uint64_t seed, const rt::RunSettings& settings);

}  // namespace g2d::test
