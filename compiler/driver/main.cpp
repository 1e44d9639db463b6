// g2d: graph grammars that generate 2D shapes.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "driver/check_command.hpp"
#include "driver/infer_command.hpp"
#include "driver/import_command.hpp"
#include "driver/big_stack.hpp"
#include "driver/build_command.hpp"
#include "driver/run_command.hpp"
#include "driver/show_command.hpp"
#include "g2d/run_options.hpp"
#include "lsp/server.hpp"
#include "studio/studio.hpp"

#include <iostream>

namespace {

int runCommandLine(int argc, char** argv) {
    CLI::App app{"g2d: a compiled language for graph grammars that generate 2D shapes"};
    app.set_version_flag("--version", "g2d 0.1.0");
    app.require_subcommand(1);

    auto* check = app.add_subcommand("check", "Check grammar files and report every error");
    std::vector<std::string> checkFiles;
    std::string format = "text";
    bool werror = false;
    check->add_option("FILE", checkFiles, ".g2d files to check")->required();
    check->add_option("--diagnostics-format", format, "text (default) or json")
        ->check(CLI::IsMember({"text", "json"}));
    check->add_flag("--werror", werror, "Treat warnings as errors");

    auto* run = app.add_subcommand("run", "Derive a grammar and write SVG (and graph JSON)");
    g2d::rt::RunRequest runRequest;
    run->add_option("FILE", runRequest.grammarFile, ".g2d grammar (with --help: also lists its parameters)")->required();
    g2d::rt::addRunOptions(*run, runRequest);
    run->footer("`g2d run FILE --help` also lists the grammar's parameters.");

    auto* show = app.add_subcommand("show", "Draw every production (mother beside daughters) and the axiom");
    g2d::ShowOptions showOptions;
    show->add_option("FILE", showOptions.file, ".g2d grammar")->required();
    show->add_option("-o,--output", showOptions.output, "OUT.html (a page) or OUT.svg")->required();

    auto* lsp = app.add_subcommand("lsp", "Serve the Language Server Protocol on stdin/stdout (for editors)");
    bool stdio = true;
    lsp->add_flag("--stdio", stdio, "Talk over stdin/stdout (the default and only transport)");

    auto* studio = app.add_subcommand("studio", "Edit a grammar in the browser and watch its picture (a local server)");
    g2d::studio::StudioOptions studioOptions;
    studio->add_option("FILE", studioOptions.file, ".g2d grammar to edit (the only file the studio writes)");
    studio->add_option("--port", studioOptions.port, "Port on 127.0.0.1 (0, the default: any free port)")
        ->check(CLI::Range(0, 65535));

    auto* emitCpp = app.add_subcommand("emit-cpp", "Write the grammar as one C++ translation unit");
    g2d::BuildOptions emitOptions;
    emitCpp->add_option("FILE", emitOptions.file, ".g2d grammar")->required();
    emitCpp->add_option("-o,--output", emitOptions.output, "The .cpp to write")->required();
    std::string factory;
    emitCpp->add_option("--factory", factory,
                        "Emit no main(); the grammar is made by `std::unique_ptr<g2d::rt::GrammarRun> NAME()`");

    auto* build = app.add_subcommand("build", "Compile the grammar into a native program (same output as g2d run)");
    g2d::BuildOptions buildOptions;
    std::string keepCpp, cxx;
    build->add_option("FILE", buildOptions.file, ".g2d grammar")->required();
    build->add_option("-o,--output", buildOptions.output, "The executable to write")->required();
    build->add_option("--cxx", cxx, "C++ compiler (default: $CXX, then c++)");
    build->add_option("-O", buildOptions.optimize, "Optimisation level: 0, 1, 2 (default), 3, s, g");
    build->add_option("--keep-cpp", keepCpp, "Also write the generated C++ to this file");
    build->add_flag("-v,--verbose", buildOptions.verbose, "Print the compiler command");

    auto* infer = app.add_subcommand("infer", "Infer a graph grammar from an example shape (Merrell 2023)");
    g2d::InferCommandOptions inferOptions;
    infer->add_option("EXAMPLE", inferOptions.example, "The example: the JSON of Merrell's app, or an SVG drawing (.svg)")->required();
    infer->add_flag("--stats", inferOptions.stats, "Print the numbers (labels, primitives, graphs, rules, time) as JSON");
    infer->add_option("-o,--output", inferOptions.output, "Write the grammar as .g2d source to this file");
    infer->add_option("--iterations", inferOptions.iterations,
                      "The written grammar's step limit (the parameter `iterations`; default 10 × the size, at least 1000)")
        ->check(CLI::Range(1, 1000000000));
    auto* sizeOption = infer->add_option("--size", inferOptions.size,
                                         "The written grammar's target number of vertices (the parameter `target_vertices`; "
                                         "default 20 × the example's)");
    infer->add_flag("--connected", inferOptions.connected,
                    "The output is one connected piece: one starter, once, and no rule that could split it (Appendix A)");
    infer->add_flag("--no-loops", inferOptions.limits.noLoops, "No loop gluing: rules make no new cycles (Appendix A)");
    infer->add_flag("--bend", inferOptions.bend, "Edges drawn bent by their label's Bend (default 10 degrees a segment; Appendix B)");
    auto* unitOption = infer->add_option("--length-unit", inferOptions.labels.lengthUnit,
                                         "Lengths of every non-rigid edge label are whole multiples of this (grid units; tiles, stairs)");
    infer->add_option("--angle-tolerance", inferOptions.labels.angleTolerance, "Degrees within which edge directions are one")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 45.0));
    infer->add_option("--max-graphs", inferOptions.limits.maxGraphs, "Stop growing the graph hierarchy at this size")
        ->capture_default_str()
        ->check(CLI::Range(1, 10'000'000));
    infer->add_option("--max-generation", inferOptions.limits.maxGeneration, "Do not grow graphs of more glues (§5.7)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    infer->add_option("--max-half-edges", inferOptions.limits.maxHalfEdges, "Do not grow graphs with more open half-edges (§5.7)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));

    auto* importCmd = app.add_subcommand("import", "Translate a grammar of the original tool (model_gen YAML) into g2d source");
    g2d::ImportCommandOptions importOptions;
    importCmd->add_option("FILE", importOptions.input, "The tool's grammar (.yml)")->required();
    importCmd->add_option("-o,--output", importOptions.output, "Write the .g2d source here (default: standard output)");
    importCmd->add_flag("-q,--quiet", importOptions.quiet, "Do not print the warnings");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        const int code = app.exit(e);
        // `g2d run FILE --help`: the file was read before the help was asked for.
        if (run->parsed() && !runRequest.grammarFile.empty()) return g2d::printGrammarParameters(runRequest.grammarFile);
        return code;
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;  // usage error
    }

    if (importCmd->parsed()) return g2d::runImport(importOptions);
    if (check->parsed()) {
        return g2d::runCheck(checkFiles,
                             format == "json" ? g2d::DiagnosticsFormat::Json : g2d::DiagnosticsFormat::Text,
                             werror);
    }
    if (emitCpp->parsed()) {
        if (!factory.empty()) {
            emitOptions.withMain = false;
            emitOptions.factory = factory;
        }
        return g2d::runEmitCpp(emitOptions);
    }
    if (build->parsed()) {
        if (!keepCpp.empty()) buildOptions.keepCpp = keepCpp;
        if (!cxx.empty()) buildOptions.cxx = cxx;
        return g2d::runBuild(buildOptions);
    }
    if (show->parsed()) return g2d::runShow(showOptions);
    if (infer->parsed()) {
        inferOptions.sizeGiven = sizeOption->count() > 0;
        inferOptions.unitGiven = unitOption->count() > 0;
        return g2d::runInfer(inferOptions);
    }
    if (lsp->parsed()) {
        std::ios::sync_with_stdio(false);
        return g2d::lsp::runLanguageServer(std::cin, std::cout);
    }
    if (run->parsed()) return g2d::runRun(runRequest);
    if (studio->parsed()) return g2d::studio::runStudio(studioOptions);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    return g2d::runWithBigStack([&] { return runCommandLine(argc, argv); });
}
