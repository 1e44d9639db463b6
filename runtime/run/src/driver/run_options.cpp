#include "g2d/run_options.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "g2d/param_parse.hpp"
#include "g2d/seed_batch.hpp"
#include "g2d/value.hpp"

namespace g2d::rt {

namespace {

// An optional output or bound, set when the option is given.
template <class T>
CLI::Option* addOptional(CLI::App& app, const std::string& name, std::optional<T>& into, const std::string& help,
                         const std::string& typeName) {
    return app.add_option_function<T>(name, [&into](const T& v) { into = v; }, help)->type_name(typeName);
}

std::string defaultText(const ParamSpec& p) {
    if (p.type == ParamType::Enum) {
        const auto& e = std::get<EnumVal>(p.defaultValue);
        return e.index >= 0 && static_cast<std::size_t>(e.index) < p.enumValues.size() ? p.enumValues[e.index] : "";
    }
    if (const auto* v = std::get_if<vec2>(&p.defaultValue)) return formatNumber(v->x) + "," + formatNumber(v->y);
    if (const auto* v = std::get_if<vec3>(&p.defaultValue)) return formatNumber(v->x) + "," + formatNumber(v->y) + "," + formatNumber(v->z);
    return toString(p.defaultValue);
}

}  // namespace

void addRunOptions(CLI::App& app, RunRequest& r) {
    addOptional(app, "-o,--output", r.svgOut,
                "SVG output (default: the grammar's name with .svg); a name ending in .png writes a PNG image instead", "FILE");
    addOptional(app, "--dpi", r.dpi, "PNG output: pixels per inch of the drawing's size in cm (default 96)", "N");
    addOptional(app, "--width", r.width, "PNG output: the image's width in pixels (the height follows; not with --dpi)", "PX");
    addOptional(app, "--json", r.jsonOut, "Graph output in NetworkX node-link JSON", "FILE");
    addOptional(app, "--obj", r.objOut,
                "Wavefront OBJ output: nodes as vertices, faces by kind with normals, edges as lines; "
                "the faces' colours go to an MTL beside it (FILE with .mtl)", "FILE");
    app.add_flag("--obj-triangles", r.objTriangles, "OBJ output: every face as triangles (for importers that split faces badly)");
    addOptional(app, "--gltf", r.gltfOut,
                "Binary glTF 2.0 output (.glb): a mesh per face kind, thick edges as tubes, colours from the styles", "FILE");
    addOptional(app, "--view", r.viewOut, "Write the model in 3D as a self-contained HTML page (drag to turn it)", "FILE");
    addOptional(app, "--view-from", r.viewFrom,
                "3D grammars: draw the SVG as seen from this direction (default 1,-2,1.5; z is up)", "X,Y,Z");
    app.add_flag("--no-svg", r.noSvg, "Write no SVG");
    app.add_flag("--svg-compact", r.svgCompact,
                 "Smaller SVG for huge drawings: each run of alike lines as one <path> (the same picture)");
    app.add_flag("--embed-images", r.embedImages,
                 "Put the images into the SVG (data: URIs) instead of linking them: a file that stands alone");
    addOptional(app, "--viewbox", r.viewBox,
                "The SVG's frame, exactly, in graph units with y up: lower left X0,Y0, upper right X1,Y1 "
                "(over the grammar's `canvas` and the frame fitted to the drawing; outside is clipped)",
                "X0,Y0,X1,Y1");
    addOptional(app, "--precision", r.precision, "Round SVG coordinates to N decimals (default: exact)", "N")
        ->check(CLI::Range(0, 15));
    CLI::Option* seed =
        app.add_option("--seed", r.seed, "Seed of the random generator (default 1)")->check(CLI::NonNegativeNumber)->type_name("N");
    app.add_option("-D,--define", r.defines, "Set a parameter (the grammar's are listed below)")
        ->allow_extra_args(false)
        ->type_name("NAME=VALUE");
    addOptional(app, "--steps", r.steps, "Global step limit (overrides the grammar's)", "N");
    app.add_flag("--stats", r.stats, "Print one JSON line of statistics on stdout");
    addOptional(app, "--max-elements", r.maxElements,
                "Stop with an error when the graph grows past N nodes + edges (default 10000000)", "N");
    addOptional(app, "--timeout", r.timeoutSeconds, "Stop with an error when the derivation runs longer than SECONDS", "SECONDS");
    app.add_flag("--keep-partial", r.keepPartial, "After an error or a bound, still write the graph of the last completed step");
    addOptional(app, "--trace", r.traceHtml, "Write the derivation step by step as a self-contained HTML page", "FILE");
    addOptional(app, "--trace-json", r.traceJson, "Write the derivation step by step as JSON", "FILE");
    app.add_flag("--verify-matches", r.verifyMatches,
                 "After every step, check the engine's kept matches against a full search (slow; an error names the first difference)");
    app.add_flag("-q,--quiet", r.quiet, "Show no progress display on stderr");
    addSeedBatchOptions(app, r, seed);
}

std::string parameterHelp(const std::vector<ParamSpec>& params) {
    if (params.empty()) return "The grammar has no parameters.";
    std::string out = "Parameters of the grammar (-D NAME=VALUE):\n";
    for (const auto& p : params) {
        std::string left = "  " + p.name + ": " + p.typeName;
        if (p.type == ParamType::Enum) {
            left += " (";
            for (std::size_t i = 0; i < p.enumValues.size(); ++i) left += (i ? " | " : "") + p.enumValues[i];
            left += ")";
        }
        if (left.size() < 30) left += std::string(30 - left.size(), ' ');
        std::string range;
        if (p.min && p.max) range = ", from " + formatNumber(*p.min) + " to " + formatNumber(*p.max);
        if (p.step) range += " in steps of " + formatNumber(*p.step);
        out += left + " default " + defaultText(p) + range + "\n";
    }
    return out;
}

std::optional<int> parseRunArguments(int argc, char** argv, const std::string& grammarFile,
                                     const std::vector<ParamSpec>& params, RunRequest& out) {
    out.grammarFile = grammarFile;
    const std::string program =
        argc > 0 && argv[0] && *argv[0] ? std::filesystem::path(argv[0]).filename().string() : std::string("grammar");
    out.program = program;
    CLI::App app{"The grammar " + std::filesystem::path(grammarFile).filename().string() +
                     ", compiled by g2d: derives it and writes SVG (and graph JSON)",
                 program};
    addRunOptions(app, out);
    app.footer(parameterHelp(params));
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
        std::fprintf(stderr, "Run with --help for the options and the grammar's parameters.\n");
        return 2;
    }
    return std::nullopt;
}

}  // namespace g2d::rt
