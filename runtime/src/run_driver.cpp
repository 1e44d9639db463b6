#include "g2d/run_driver.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <unistd.h>

#include "g2d/atomic_file.hpp"
#include "g2d/source_excerpt.hpp"

namespace g2d::rt {

namespace {

int usageError(const std::string& message) {
    std::fprintf(stderr, "g2d run: error: %s\n", message.c_str());
    return 2;
}

// Parameter values: defaults, then -D overrides. Returns an error message or "".
std::string parameterValues(const std::vector<ParamSpec>& specs, const std::vector<std::string>& defines,
                            std::vector<Value>& out) {
    for (const auto& p : specs) out.push_back(p.defaultValue);
    for (const auto& d : defines) {
        const auto eq = d.find('=');
        if (eq == std::string::npos || eq == 0) return "-D " + d + ": expected NAME=VALUE";
        const std::string name = d.substr(0, eq), text = d.substr(eq + 1);
        std::size_t index = specs.size();
        for (std::size_t i = 0; i < specs.size(); ++i)
            if (specs[i].name == name) index = i;
        if (index == specs.size()) {
            std::string known;
            for (const auto& p : specs) known += (known.empty() ? "" : ", ") + p.name;
            return "-D " + name + ": the grammar has no parameter `" + name + "`" +
                   (known.empty() ? " (it declares none)" : " (its parameters: " + known + ")");
        }
        const auto& p = specs[index];
        auto v = parseParamValue(p.type, text, p.enumId, p.enumValues);
        if (!v) {
            std::string hint = p.type == ParamType::Vec2 ? " (write x,y)" : "";
            if (p.type == ParamType::Enum) {
                hint = " (one of";
                for (const auto& e : p.enumValues) hint += " " + e;
                hint += ")";
            }
            return "-D " + name + "=" + text + ": not a valid " + p.typeName + hint;
        }
        out[index] = std::move(*v);
    }
    return "";
}

// Shows steps, elements and rate on a terminal, at most five times a second.
class Progress {
public:
    Progress() : enabled_(isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()), last_(start_) {}
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

const char* stopName(StopReason r) { return r == StopReason::Terminal ? "terminal" : "step_limit"; }

}  // namespace

std::string renderLocatedError(const SourceLocation& at, const std::string& message) {
    std::string out = at.file + ":" + std::to_string(at.line) + ":" + std::to_string(at.col) + ": error: " + message + "\n";
    if (at.line == 0) return out;
    const Excerpt ex = excerptLine(at.lineText, at.col, at.endCol);
    return out + "  " + ex.line + "\n  " + std::string(ex.pad, ' ') + "^" + std::string(ex.width - 1, '~') + "\n";
}

DerivedRun deriveGrammar(GrammarRun& grammar, const std::vector<Value>& params, std::uint64_t seed,
                         const RunLimits& runLimits, const StepObserver& observer, RunProgress* progress,
                         TraceRecorder* trace) {
    Rng rng(seed);
    grammar.start(params, rng);
    if (trace) trace->started();
    if (progress) *progress = RunProgress{true, 0};
    DerivationLimits limits;
    const std::optional<long long> grammarLimit = grammar.stepLimit();
    limits.steps = runLimits.steps ? runLimits.steps : grammarLimit ? grammarLimit : kDefaultStepLimit;
    limits.perPriority = grammar.priorityLimits();
    limits.maxElements = runLimits.maxElements;
    limits.timeoutSeconds = runLimits.timeoutSeconds;
    DerivedRun out;
    out.result = derive(
        grammar.graph(), grammar.rules(), rng, limits,
        [&](long long s, const Graph& g) {
            if (progress) progress->step = s;
            if (observer) observer(s, g);
        },
        trace);
    out.hitDefaultLimit = out.result.stopped == StopReason::StepLimit && !runLimits.steps && !grammarLimit;
    return out;
}

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

int runGrammar(const RunRequest& request, GrammarRun& grammar) {
    std::vector<Value> params;
    if (std::string err = parameterValues(grammar.params(), request.defines, params); !err.empty())
        return usageError(err);
    if (request.steps && *request.steps < 0) return usageError("--steps must not be negative");
    if (request.maxElements && *request.maxElements <= 0) return usageError("--max-elements must be positive");
    if (request.timeoutSeconds && !(*request.timeoutSeconds > 0 && *request.timeoutSeconds < 1e9))
        return usageError("--timeout must be a positive number of seconds");

    // Outputs are opened first, so an unwritable path fails before the work.
    std::unique_ptr<AtomicFile> svgFile, jsonFile, traceHtmlFile, traceJsonFile;
    try {
        if (!request.noSvg)
            svgFile = std::make_unique<AtomicFile>(
                request.svgOut.value_or(std::filesystem::path(request.grammarFile).stem().string() + ".svg"));
        if (request.jsonOut) jsonFile = std::make_unique<AtomicFile>(*request.jsonOut);
        if (request.traceHtml) traceHtmlFile = std::make_unique<AtomicFile>(*request.traceHtml);
        if (request.traceJson) traceJsonFile = std::make_unique<AtomicFile>(*request.traceJson);
    } catch (const OutputError& e) {
        std::fprintf(stderr, "g2d run: error: %s\n", e.what());
        return 1;
    }

    RunLimits limits;
    limits.steps = request.steps;
    limits.maxElements = request.maxElements ? static_cast<std::size_t>(*request.maxElements) : kDefaultMaxElements;
    limits.timeoutSeconds = request.timeoutSeconds;
    RunProgress progress;
    std::unique_ptr<TraceRecorder> trace;
    if (traceHtmlFile || traceJsonFile) trace = std::make_unique<TraceRecorder>(grammar);
    DerivationResult result;
    std::string stopped;
    int status = 0;
    try {
        Progress display;
        const DerivedRun derived =
            deriveGrammar(grammar, params, request.seed, limits, [&](long long s, const Graph& g) { display.update(s, g); },
                          &progress, trace.get());
        result = derived.result;
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
        std::fprintf(stderr, "g2d run: error: %s\n", e.what());
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
    if (status != 0 && !(request.keepPartial && progress.started)) return status;
    if (status != 0) result.steps = progress.step;

    try {
        const Graph& graph = grammar.graph();
        const std::string svg = svgFile || traceHtmlFile ? writeSvg(grammar.drawItems(), grammar.svgDefs()) : "";
        if (svgFile) svgFile->commit(svg);
        if (trace) {
            const std::string name = std::filesystem::path(request.grammarFile).filename().string();
            const std::string data = trace->json(name, request.seed, stopped);
            if (traceJsonFile) traceJsonFile->commit(data);
            if (traceHtmlFile) traceHtmlFile->commit(writeTracePage(data, svg, name));
        }
        if (jsonFile) {
            const std::vector<std::pair<std::string, Value>> meta = {
                {"grammar", std::filesystem::path(request.grammarFile).filename().string()},
                {"seed", static_cast<long long>(request.seed)},
                {"steps", result.steps},
                {"stopped", stopped}};
            jsonFile->commit(writeJson(graph, grammar.jsonSchema(), meta,
                                       [&](bool isEdge, std::uint32_t id, int a) { return grammar.attribute(isEdge, id, a); }));
        }
        if (request.stats)
            std::printf("{\"steps\": %lld, \"nodes\": %zu, \"edges\": %zu, \"seconds\": %s, \"seed\": %llu, "
                        "\"stopped\": \"%s\", \"applications\": %lld, \"lookahead_guesses\": %lld, \"lookahead_hits\": %lld, "
                        "\"repairs\": %lld, \"repairs_skipped\": %lld}\n",
                        result.steps, graph.nodeCount(), graph.edgeCount(), formatNumber(result.seconds).c_str(),
                        static_cast<unsigned long long>(request.seed), stopped.c_str(), result.applications,
                        result.lookaheadGuesses, result.lookaheadHits, result.setRepairs, result.setRepairsSkipped);
    } catch (const OutputError& e) {
        std::fprintf(stderr, "g2d run: error: %s\n", e.what());
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
