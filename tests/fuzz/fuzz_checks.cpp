#include "fuzz_checks.hpp"

#include <cstdio>
#include <optional>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "driver/big_stack.hpp"
#include "front/compile.hpp"
#include "g2d/json_writer.hpp"
#include "g2d/run_driver.hpp"
#include "g2d/svg_writer.hpp"
#include "interp/interpreted_run.hpp"

namespace g2d::fuzz {

void violated(const std::string& what) {
    std::fprintf(stderr, "fuzz check failed: %s\n", what.c_str());
    std::abort();
}

namespace {

// Inputs live nowhere on disk: imports resolve in a folder that does not
// exist (absolute imports still reach real files, which is fine: the loader
// refuses anything but regular files of bounded size).
CompileResult compileBytes(const std::uint8_t* data, std::size_t size) {
    LoadOptions options;
    const std::string text(reinterpret_cast<const char*>(data), size);
    return compileSource("/nonexistent-g2d-fuzz/input.g2d", text, options);
}

}  // namespace

void checkDiagnostics(const CompileResult& r) {
    bool anyError = false;
    for (const auto& d : r.diags.sorted()) {
        anyError = anyError || d.severity == Severity::Error;
        if (d.message.empty()) violated("a diagnostic without a message");
        if (d.span.file == kNoFile) violated("a diagnostic without a file: " + d.message);
        if (d.span.file >= r.sources.size()) violated("a diagnostic in an unknown file: " + d.message);
        const auto& file = r.sources.file(d.span.file);
        if (d.span.line > 0) {
            std::uint32_t lines = 1;
            for (char c : file.text) lines += c == '\n';
            if (d.span.line > lines) violated("a diagnostic past the last line: " + d.message);
        }
        (void)renderText(d, r.sources, false);
    }
    (void)renderJson(r.diags.sorted(), r.sources);
    if (anyError && r.program) violated("a program despite errors");
    if (!anyError && !r.program) violated("no program and no error");
}

void checkFrontEnd(const std::uint8_t* data, std::size_t size) {
    runWithBigStack([&] { checkFrontEndHere(data, size); return 0; });
}

void checkInterpreter(const std::uint8_t* data, std::size_t size) {
    runWithBigStack([&] { checkInterpreterHere(data, size); return 0; });
}

void checkFrontEndHere(const std::uint8_t* data, std::size_t size) {
    try {
        checkDiagnostics(compileBytes(data, size));
    } catch (const std::exception& e) {
        violated(std::string("the front end threw: ") + e.what());
    }
}

void checkInterpreterHere(const std::uint8_t* data, std::size_t size) {
    CompileResult r;
    try {
        r = compileBytes(data, size);
    } catch (const std::exception& e) {
        violated(std::string("the front end threw: ") + e.what());
    }
    checkDiagnostics(r);
    if (!r.program) return;
    interp::InterpretedRun run(*r.program, &r.sources);
    rt::RunSettings settings;
    settings.steps = 300;
    settings.maxElements = 20000;
    settings.timeoutSeconds = 2.0;
    settings.verifyMatches = true;
    try {
        std::vector<rt::Value> params;
        for (const auto& p : run.params()) params.push_back(p.defaultValue);
        rt::DerivedRun derived;
        rt::deriveGrammar(run, params, 7, settings, derived);
    } catch (const std::exception& e) {
        if (auto wrong = unexpectedRunFailure(e, run)) violated("in the derivation: " + *wrong);
    }
    // Whatever the derivation reached is a completed step: it must draw and write.
    try {
        (void)rt::writeSvg(run.drawItems(), run.svgDefs());
        (void)rt::writeJson(run.graph(), run.jsonSchema(), {},
                            [&](rt::ElemClass cls, std::uint32_t id, int a) { return run.attribute(cls, id, a); });
    } catch (const std::exception& e) {
        if (auto wrong = unexpectedRunFailure(e, run)) violated("while drawing: " + *wrong);
    }
}

std::optional<std::string> unexpectedRunFailure(const std::exception& e, const rt::GrammarRun& run) {
    const std::string what = e.what();
    // A bound: the graph is that of the last completed step, and g2d run says which bound.
    if (dynamic_cast<const rt::RunawayError*>(&e)) {
        if (what.empty()) return "a bound without a message";
        return std::nullopt;
    }
    // A run-time error in the grammar: g2d run shows it at its place in the source.
    if (run.locate(e)) {
        if (what.empty()) return "a run-time error without a message";
        return std::nullopt;
    }
    // Anything else (std::logic_error, std::bad_variant_access, std::out_of_range, an
    // OpError that escaped its location, ...) is a fault of g2d's.
    return std::string("an error g2d cannot locate: ") + what;
}

}  // namespace g2d::fuzz
