#include "g2d/run_driver.hpp"

#include "g2d/projection.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <unistd.h>

#include "g2d/atomic_file.hpp"
#include "g2d/export_style.hpp"
#include "g2d/gltf_writer.hpp"
#include "g2d/image_links.hpp"
#include "g2d/parameter_values.hpp"
#include "g2d/png_writer.hpp"
#include "g2d/run_outputs.hpp"
#include "g2d/run_stats.hpp"
#include "g2d/seed_batch.hpp"
#include "g2d/trace.hpp"
#include "g2d/view_page.hpp"

namespace g2d::rt {

namespace {

// The OBJ's materials: beside it, its name with .mtl.
std::string mtlPath(const std::string& obj) { return std::filesystem::path(obj).replace_extension(".mtl").string(); }

int usageError(const RunRequest& request, const std::string& message) {
    std::fprintf(stderr, "%s: error: %s\n", request.program.c_str(), message.c_str());
    return 2;
}

std::string trimmed(const std::string& s) {
    const auto first = s.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

}  // namespace

std::string parameterValues(const std::vector<ParamSpec>& specs, const std::vector<std::string>& defines,
                            std::vector<Value>& out) {
    for (const auto& p : specs) out.push_back(p.defaultValue);
    for (const auto& d : defines) {
        const auto eq = d.find('=');
        if (eq == std::string::npos || trimmed(d.substr(0, eq)).empty())
            return "parameter setting `" + d + "`: expected NAME=VALUE";
        // `-D "gens = 3"` reads as gens=3.
        const std::string name = trimmed(d.substr(0, eq)), text = trimmed(d.substr(eq + 1));
        std::size_t index = specs.size();
        for (std::size_t i = 0; i < specs.size(); ++i)
            if (specs[i].name == name) index = i;
        if (index == specs.size()) {
            std::string known;
            for (const auto& p : specs) known += (known.empty() ? "" : ", ") + p.name;
            return "the grammar has no parameter `" + name + "`" +
                   (known.empty() ? " (it declares none)" : " (its parameters: " + known + ")");
        }
        std::string why;
        auto v = parameterValue(specs[index], text, why);
        if (!v) return why;
        out[index] = std::move(*v);
    }
    return "";
}

namespace {

// Shows steps, elements and rate on a terminal, at most five times a second.
class Progress {
public:
    explicit Progress(bool wanted) : enabled_(wanted && isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()), last_(start_) {}
    void update(long long step, const Graph& g) {
        if (!enabled_ || (step & 255) != 0) return;
        auto now = std::chrono::steady_clock::now();
        if (now - last_ < std::chrono::milliseconds(200)) return;
        last_ = now;
        shown_ = true;
        const double secs = std::chrono::duration<double>(now - start_).count();
        std::fprintf(stderr, "\r  step %lld  |  %zu elements  |  %.0f steps/s   ", step, g.nodeCount() + g.edgeCount(),
                     secs > 0 ? static_cast<double>(step) / secs : 0.0);
    }
    ~Progress() {
        if (shown_) std::fprintf(stderr, "\r%60s\r", "");
    }

private:
    bool enabled_, shown_ = false;
    std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace

namespace {

// A run-time error, with the rule and step it happened in and, when the
// back end can tell, the source line.
void reportRunError(const RunRequest& request, GrammarRun& grammar, const std::exception& e, long long step) {
    const std::string rule = grammar.currentRule();
    const std::string where =
        rule.empty() ? " (before the first step)" : " (in rule `" + rule + "`, step " + std::to_string(step + 1) + ")";
    if (auto at = grammar.locate(e))
        std::fputs(renderLocatedError(*at, e.what() + where).c_str(), stderr);
    else
        std::fprintf(stderr, "%s: error: %s%s\n", request.grammarFile.c_str(), e.what(), where.c_str());
}

}  // namespace

// Why --dpi or --width cannot apply, or "".
std::string pngOptionError(const RunRequest& request) {
    if (!request.dpi && !request.width) return "";
    const char* option = request.dpi ? "--dpi" : "--width";
    if (request.dpi && request.width)
        return "--dpi and --width both set the PNG's size: give one of them (--width PX fixes the width, the height follows)";
    if (request.noSvg || !request.svgOut || !isPngPath(*request.svgOut))
        return std::string(option) + " applies to PNG output only: write the image with -o FILE.png";
    if (request.dpi && !(*request.dpi > 0 && *request.dpi <= 10000)) return "--dpi must be a positive number (at most 10000)";
    if (request.width && !(*request.width > 0 && *request.width <= 32767)) return "--width must be between 1 and 32767 pixels";
    return "";
}

int runGrammar(const RunRequest& request, GrammarRun& grammar) {
    if (std::string err = pngOptionError(request); !err.empty()) return usageError(request, err);
    std::optional<ViewBox> viewBox;   // over the grammar's canvas
    if (request.viewBox) {
        std::string why;
        viewBox = parseViewBox(*request.viewBox, why);
        if (!viewBox) return usageError(request, "--viewbox " + *request.viewBox + ": " + why);
    }
    if (request.objTriangles && !request.objOut) return usageError(request, "--obj-triangles applies to OBJ output only: give --obj FILE");
    if (request.objOut && std::filesystem::path(*request.objOut).extension() == ".mtl")
        return usageError(request, "--obj " + *request.objOut + ": the OBJ's materials go beside it with .mtl; name the OBJ FILE.obj");
    if (request.seeds) return runSeedBatch(request, grammar);   // many seeds: one runGrammar per seed, in workers
    std::vector<Value> params;
    if (std::string err = parameterValues(grammar.params(), request.defines, params); !err.empty())
        return usageError(request, err);
    if (request.steps && *request.steps < 0) return usageError(request, "--steps must not be negative");
    ViewProjection view = viewFrom(kDefaultViewFrom);
    if (request.viewFrom) {
        const auto from = parseParamValue(ParamType::Vec3, *request.viewFrom, -1, {}, "vec3");
        if (!from) return usageError(request, "--view-from " + *request.viewFrom + ": expected three numbers X,Y,Z");
        try {
            view = viewFrom(std::get<vec3>(*from));
        } catch (const std::invalid_argument& e) {
            return usageError(request, std::string("--view-from: ") + e.what());
        }
    }
    if (request.maxElements && *request.maxElements <= 0) return usageError(request, "--max-elements must be positive");
    if (request.timeoutSeconds && !(*request.timeoutSeconds > 0 && *request.timeoutSeconds < 1e9))
        return usageError(request, "--timeout must be a positive number of seconds");

    // Outputs are opened first, so an unwritable path fails before the work.
    std::unique_ptr<AtomicFile> svgFile, jsonFile, objFile, mtlFile, gltfFile, viewFile, traceHtmlFile, traceJsonFile;
    try {
        if (!request.noSvg)
            svgFile = std::make_unique<AtomicFile>(
                request.svgOut.value_or(std::filesystem::path(request.grammarFile).stem().string() + ".svg"));
        if (request.jsonOut) jsonFile = std::make_unique<AtomicFile>(*request.jsonOut);
        if (request.objOut) objFile = std::make_unique<AtomicFile>(*request.objOut);
        if (request.objOut) mtlFile = std::make_unique<AtomicFile>(mtlPath(*request.objOut));
        if (request.gltfOut) gltfFile = std::make_unique<AtomicFile>(*request.gltfOut);
        if (request.viewOut) viewFile = std::make_unique<AtomicFile>(*request.viewOut);
        if (request.traceHtml) traceHtmlFile = std::make_unique<AtomicFile>(*request.traceHtml);
        if (request.traceJson) traceJsonFile = std::make_unique<AtomicFile>(*request.traceJson);
    } catch (const OutputError& e) {
        std::fprintf(stderr, "%s: error: %s\n", request.program.c_str(), e.what());
        return 1;
    }

    RunSettings settings;
    settings.steps = request.steps;
    settings.maxElements = request.maxElements ? static_cast<std::size_t>(*request.maxElements) : kDefaultMaxElements;
    settings.timeoutSeconds = request.timeoutSeconds;
    settings.verifyMatches = request.verifyMatches;
    RunProgress progress;
    std::unique_ptr<TraceRecorder> trace;
    if (traceHtmlFile || traceJsonFile) trace = std::make_unique<TraceRecorder>(grammar);
    DerivedRun derived;
    const DerivationResult& result = derived.result;   // complete, or as far as the derivation got
    std::string stopped;
    int status = 0;
    try {
        Progress display(!request.quiet);
        deriveGrammar(grammar, params, request.seed, settings, derived,
                      [&](long long s, const Graph& g) { display.update(s, g); }, &progress, trace.get());
        stopped = stopName(result.stopped);
        if (derived.hitDefaultLimit) {
            std::fprintf(stderr,
                         "%s: error: stopped at the default limit of %lld steps: the grammar may not terminate "
                         "(set `limit N;` or pass --steps N%s)\n",
                         request.grammarFile.c_str(), kDefaultStepLimit,
                         request.keepPartial ? "" : "; --keep-partial writes the graph so far");
            stopped = "default_step_limit";
            status = 1;
        }
    } catch (const OutputError& e) {
        std::fprintf(stderr, "%s: error: %s\n", request.program.c_str(), e.what());
        return 1;
    } catch (const RunawayError& e) {
        std::fprintf(stderr, "%s: error: %s\n", request.grammarFile.c_str(), e.what());
        stopped = e.bound();
        status = 1;
    } catch (const std::exception& e) {
        reportRunError(request, grammar, e, progress.step);
        stopped = "error";
        status = 1;
    }
    if (request.outcome)   // a batch's summary row (seed_batch.cpp)
        *request.outcome = RunOutcome{result.steps, grammar.graph().nodeCount() + grammar.graph().edgeCount(),
                                      grammar.graph().faceCount(), stopped};
    if (status != 0 && !(request.keepPartial && progress.started)) return status;

    try {
        const Graph& graph = grammar.graph();
        const std::string name = std::filesystem::path(request.grammarFile).filename().string();
        RunOutputs outputs;
        outputs.svgOptions.compact = request.svgCompact;
        outputs.svgOptions.precision = request.precision;
        outputs.svgOptions.viewBox = viewBox ? viewBox : derived.canvas;   // --viewbox > canvas > fitted
        outputs.view = view;
        outputs.grammarName = name;
        outputs.seed = request.seed;
        outputs.steps = result.steps;
        outputs.stopped = stopped;
        // Images are named relative to the grammar; the SVG links them from
        // where it is written (a PNG is rendered with the grammar's folder as base).
        const bool png = svgFile && request.svgOut && isPngPath(*request.svgOut);
        const std::string svgPlace = svgFile ? request.svgOut.value_or(std::filesystem::path(request.grammarFile).stem().string() + ".svg")
                                             : request.traceHtml.value_or(".");
        ImageLinks images(request.grammarFile, svgPlace, request.embedImages);
        if (!png || request.embedImages)
            outputs.svgOptions.imageHref = [&images](const std::string& href) { return images.href(href); };
        // The SVG is streamed into its file, but made whole in memory for a
        // PNG (which librsvg renders) and for the trace page (which embeds it).
        StringOut svgText;
        const bool svgWhole = png || traceHtmlFile;
        outputs.svg = svgWhole ? static_cast<TextOut*>(&svgText) : svgFile.get();
        outputs.json = jsonFile.get();
        outputs.obj = objFile.get();
        outputs.mtl = mtlFile.get();
        if (request.objOut) outputs.mtlName = std::filesystem::path(mtlPath(*request.objOut)).filename().string();
        outputs.objTriangles = request.objTriangles;
        writeRunOutputs(grammar, outputs);
        // The page is made before any output is committed: a face it cannot
        // draw leaves no file written.
        std::string viewPage;
        if (viewFile) {
            try {
                ViewModel model = viewModelOf(graph, grammar.drawItems(), name, grammar.jsonSchema().kindNames);
                if (grammar.jsonSchema().space3d) model.home = view.toward;   // the SVG's view, z up
                viewPage = writeViewPage(model);
            } catch (const std::runtime_error& e) {
                throw OutputError("cannot write `" + *request.viewOut + "`: " + e.what());
            }
        }
        // Made before any file is committed: a face glTF cannot draw leaves none written.
        std::string glb;
        if (gltfFile)
            glb = writeGltf(graph, grammar.jsonSchema(), [&](ElemClass cls, std::uint32_t id, DrawItem& it) { grammar.drawItem(cls, id, it); }, name);
        std::string svg;
        if (svgWhole) svg = std::move(svgText.text());
        if (png) {
            PngOptions png;
            png.dpi = request.dpi;
            png.width = request.width;
            png.baseFile = std::filesystem::absolute(request.grammarFile).string();
            std::string bytes;
            try {
                bytes = renderPng(svg, png);
            } catch (const std::runtime_error& e) {
                throw OutputError("cannot write `" + *request.svgOut + "`: " + e.what());
            }
            svgFile->commit(bytes);
        } else if (svgFile) {
            if (svgWhole)
                svgFile->commit(svg);
            else
                svgFile->commit();
        }
        if (trace) {
            const std::string data = trace->json(name, request.seed, stopped);
            if (traceJsonFile) traceJsonFile->commit(data);
            if (traceHtmlFile) traceHtmlFile->commit(writeTracePage(data, svg, name, grammar.jsonSchema().space3d));
        }
        if (jsonFile) jsonFile->commit();
        if (objFile) objFile->commit();
        if (mtlFile) mtlFile->commit();
        if (gltfFile) gltfFile->commit(glb);
        if (viewFile) viewFile->commit(viewPage);
        if (request.stats) std::fputs(runStatsLine(result, graph, request.seed, stopped).c_str(), stdout);
    } catch (const OutputError& e) {
        std::fprintf(stderr, "%s: error: %s\n", request.program.c_str(), e.what());
        return 1;
    } catch (const ExportError& e) {
        std::fprintf(stderr, "%s: error: %s; no output written\n", request.grammarFile.c_str(), e.what());
        return 1;
    } catch (const std::exception& e) {
        reportRunError(request, grammar, e, progress.step);
        return 1;
    }
    if (status != 0)
        std::fprintf(stderr, "%s: note: wrote the graph of step %lld, the last completed (--keep-partial)\n",
                     request.grammarFile.c_str(), result.steps);
    return status;
}

}  // namespace g2d::rt
