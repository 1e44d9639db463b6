#include "g2d/run_driver.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <unistd.h>

#include "g2d/atomic_file.hpp"

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
    std::string line = at.lineText;
    for (auto& c : line)
        if (c == '\t') c = ' ';
    out += "  " + line + "\n  ";
    std::size_t pad = 0;
    for (std::size_t i = 0, c = 1; i < line.size() && c < at.col; ++c) {
        ++i;
        while (i < line.size() && (static_cast<unsigned char>(line[i]) & 0xC0) == 0x80) ++i;
        ++pad;
    }
    out += std::string(pad, ' ') + "^";
    if (at.endCol > at.col + 1) out += std::string(at.endCol - at.col - 1, '~');
    return out + "\n";
}

DerivedRun deriveGrammar(GrammarRun& grammar, const std::vector<Value>& params, std::uint64_t seed,
                         std::optional<long long> steps, const StepObserver& observer, long long* lastStep,
                         std::size_t maxElements) {
    Rng rng(seed);
    grammar.start(params, rng);
    DerivationLimits limits;
    const std::optional<long long> grammarLimit = grammar.stepLimit();
    limits.steps = steps ? steps : grammarLimit ? grammarLimit : kDefaultStepLimit;
    limits.perPriority = grammar.priorityLimits();
    limits.maxElements = maxElements;
    DerivedRun out;
    out.result = derive(grammar.graph(), grammar.rules(), rng, limits, [&](long long s, const Graph& g) {
        if (lastStep) *lastStep = s;
        if (observer) observer(s, g);
    });
    out.hitDefaultLimit = out.result.stopped == StopReason::StepLimit && !steps && !grammarLimit;
    return out;
}

int runGrammar(const RunRequest& request, GrammarRun& grammar) {
    std::vector<Value> params;
    if (std::string err = parameterValues(grammar.params(), request.defines, params); !err.empty())
        return usageError(err);
    if (request.steps && *request.steps < 0) return usageError("--steps must not be negative");
    if (request.maxElements && *request.maxElements <= 0) return usageError("--max-elements must be positive");

    // Outputs are opened first, so an unwritable path fails before the work.
    std::unique_ptr<AtomicFile> svgFile, jsonFile;
    try {
        if (!request.noSvg)
            svgFile = std::make_unique<AtomicFile>(
                request.svgOut.value_or(std::filesystem::path(request.grammarFile).stem().string() + ".svg"));
        if (request.jsonOut) jsonFile = std::make_unique<AtomicFile>(*request.jsonOut);
    } catch (const OutputError& e) {
        std::fprintf(stderr, "g2d run: error: %s\n", e.what());
        return 1;
    }

    long long step = 0;
    try {
        Progress progress;
        const DerivedRun derived = deriveGrammar(grammar, params, request.seed, request.steps,
                                                 [&](long long s, const Graph& g) { progress.update(s, g); }, &step,
                                                 request.maxElements ? static_cast<std::size_t>(*request.maxElements)
                                                                     : kDefaultMaxElements);
        const DerivationResult& result = derived.result;
        if (derived.hitDefaultLimit)
            std::fprintf(stderr,
                         "%s: warning: stopped at the default limit of %lld steps; the grammar may not terminate "
                         "(set `limit N;` or pass --steps N)\n",
                         request.grammarFile.c_str(), kDefaultStepLimit);

        const Graph& graph = grammar.graph();
        if (svgFile) svgFile->commit(writeSvg(grammar.drawItems(), grammar.svgDefs()));
        if (jsonFile) {
            const std::vector<std::pair<std::string, Value>> meta = {
                {"grammar", std::filesystem::path(request.grammarFile).filename().string()},
                {"seed", static_cast<long long>(request.seed)},
                {"steps", result.steps},
                {"stopped", std::string(stopName(result.stopped))}};
            jsonFile->commit(writeJson(graph, grammar.jsonSchema(), meta,
                                       [&](bool isEdge, std::uint32_t id, int a) { return grammar.attribute(isEdge, id, a); }));
        }
        if (request.stats)
            std::printf("{\"steps\": %lld, \"nodes\": %zu, \"edges\": %zu, \"seconds\": %s, \"seed\": %llu, "
                        "\"stopped\": \"%s\", \"applications\": %lld}\n",
                        result.steps, graph.nodeCount(), graph.edgeCount(), formatNumber(result.seconds).c_str(),
                        static_cast<unsigned long long>(request.seed), stopName(result.stopped), result.applications);
    } catch (const OutputError& e) {
        std::fprintf(stderr, "g2d run: error: %s\n", e.what());
        return 1;
    } catch (const RunawayError& e) {
        std::fprintf(stderr, "%s: error: %s\n", request.grammarFile.c_str(), e.what());
        return 1;
    } catch (const std::exception& e) {
        const std::string rule = grammar.currentRule();
        const std::string where = rule.empty() ? " (before the first step)"
                                               : " (in rule `" + rule + "`, step " + std::to_string(step + 1) + ")";
        if (auto at = grammar.locate(e))
            std::fputs(renderLocatedError(*at, e.what() + where).c_str(), stderr);
        else
            std::fprintf(stderr, "%s: error: %s%s\n", request.grammarFile.c_str(), e.what(), where.c_str());
        return 1;
    }
    return 0;
}

}  // namespace g2d::rt
