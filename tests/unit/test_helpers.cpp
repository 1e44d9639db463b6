#include "test_helpers.hpp"

#include <stdexcept>

namespace g2d::test {

CompileResult compile(const std::string& text, const std::string& name) {
    LoadOptions options;
    options.importDirs = {G2D_STDLIB_DIR};
    return compileSource(std::string(G2D_SOURCE_DIR) + "/tests/unit/" + name, text, options);
}

std::vector<std::string> diagnosticLines(const CompileResult& r) {
    std::vector<std::string> out;
    for (const auto& d : r.diags.sorted()) {
        const char* sev = d.severity == Severity::Error ? "error" : d.severity == Severity::Warning ? "warning" : "note";
        out.push_back(std::to_string(d.span.line) + ":" + std::to_string(d.span.col) + ": " + sev + ": " + d.message);
    }
    return out;
}

std::string firstError(const CompileResult& r) {
    for (const auto& d : r.diags.sorted())
        if (d.severity == Severity::Error)
            return std::to_string(d.span.line) + ":" + std::to_string(d.span.col) + ": " + d.message;
    return "";
}

std::string prelude() {
    return "node P { w: float = 1; }\n"
           "edge E directed { n: int = 0; }\n"
           "edge U { }\n"
           "axiom { a: P at (0, 0); b: P at (1, 0); a -[E]-> b; a -[U]- b; }\n";
}

InterpreterStart startInterpreter(const ir::Program& prog, rt::Rng& rng) {
    interp::ProgramState state;
    rt::Graph graph = interp::startRun(prog, interp::defaultParams(prog), rng, state);
    return InterpreterStart{std::move(state), std::move(graph)};
}

rt::RunSettings verified(std::optional<long long> steps) {
    rt::RunSettings s;
    s.steps = steps;
    s.verifyMatches = true;
    return s;
}

SnippetRun runSnippet(const std::string& text, std::uint64_t seed, const rt::RunSettings& settings) {
    SnippetRun run;
    run.compiled = std::make_unique<CompileResult>(compile(text));
    if (!run.compiled->program) throw std::runtime_error("does not compile: " + firstError(*run.compiled));
    const ir::Program& prog = *run.compiled->program;
    static_cast<interp::RunResult&>(run) = interp::runProgram(prog, interp::defaultParams(prog), seed, settings);
    return run;
}

}  // namespace g2d::test
