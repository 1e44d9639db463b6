#include "driver/run_command.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <unistd.h>

#include "driver/compile.hpp"
#include "g2d/atomic_file.hpp"
#include "g2d/derivation.hpp"
#include "g2d/param_parse.hpp"
#include "interp/drawing.hpp"
#include "interp/run_program.hpp"

namespace g2d {

namespace {

bool colorStderr() { return isatty(STDERR_FILENO) && !std::getenv("NO_COLOR"); }

void printDiagnostics(const CompileResult& r) {
    for (const auto& d : r.diags.sorted()) std::fputs(renderText(d, r.sources, colorStderr()).c_str(), stderr);
}

int usageError(const std::string& message) {
    std::fprintf(stderr, "g2d run: error: %s\n", message.c_str());
    return 2;
}

rt::ParamType paramType(const ir::Type& t) {
    switch (t.kind) {
    case ir::TypeKind::Int: return rt::ParamType::Int;
    case ir::TypeKind::Float: return rt::ParamType::Float;
    case ir::TypeKind::Bool: return rt::ParamType::Bool;
    case ir::TypeKind::Vec2: return rt::ParamType::Vec2;
    case ir::TypeKind::Enum: return rt::ParamType::Enum;
    default: return rt::ParamType::String;
    }
}

// Parameter values: defaults, then -D overrides. Returns an error message or "".
std::string parameterValues(const ir::Program& prog, const std::vector<std::string>& defines,
                            std::vector<rt::Value>& out) {
    out = interp::defaultParams(prog);
    for (const auto& d : defines) {
        const auto eq = d.find('=');
        if (eq == std::string::npos || eq == 0) return "-D " + d + ": expected NAME=VALUE";
        const std::string name = d.substr(0, eq), text = d.substr(eq + 1);
        std::size_t index = prog.params.size();
        for (std::size_t i = 0; i < prog.params.size(); ++i)
            if (prog.params[i].name == name) index = i;
        if (index == prog.params.size()) {
            std::string known;
            for (const auto& p : prog.params) known += (known.empty() ? "" : ", ") + p.name;
            return "-D " + name + ": the grammar has no parameter `" + name + "`" +
                   (known.empty() ? " (it declares none)" : " (its parameters: " + known + ")");
        }
        const auto& p = prog.params[index];
        std::vector<std::string> enumValues;
        if (p.type.kind == ir::TypeKind::Enum) enumValues = prog.enums[p.type.enumId].values;
        auto v = rt::parseParamValue(paramType(p.type), text, p.type.enumId, enumValues);
        if (!v) {
            std::string hint = p.type.kind == ir::TypeKind::Vec2 ? " (write x,y)" : "";
            if (p.type.kind == ir::TypeKind::Enum) {
                hint = " (one of";
                for (const auto& e : enumValues) hint += " " + e;
                hint += ")";
            }
            return "-D " + name + "=" + text + ": not a valid " + ir::typeName(p.type, prog) + hint;
        }
        out[index] = std::move(*v);
    }
    return "";
}

void reportRuntimeError(const CompileResult& r, const interp::EvalError& e, const interp::RunFailure& failure) {
    Diagnostic d;
    d.span = e.span;
    d.message = e.what();
    if (!failure.rule.empty())
        d.message += " (in rule `" + failure.rule + "`, step " + std::to_string(failure.step) + ")";
    else
        d.message += " (before the first step)";
    std::fputs(renderText(d, r.sources, colorStderr()).c_str(), stderr);
}

// Shows steps, elements and rate on a terminal, at most five times a second.
class Progress {
public:
    Progress() : enabled_(isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()), last_(start_) {}
    void update(long long step, const rt::Graph& g) {
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

int runRun(const RunOptions& options) {
    LoadOptions load;
    load.importDirs = defaultImportDirs();
    CompileResult compiled = compileFile(options.file, load);
    printDiagnostics(compiled);
    if (!compiled.program) return 1;
    const ir::Program& prog = *compiled.program;

    std::vector<rt::Value> params;
    if (std::string err = parameterValues(prog, options.defines, params); !err.empty()) return usageError(err);
    if (options.steps && *options.steps < 0) return usageError("--steps must not be negative");

    // Outputs are opened first, so an unwritable path fails before the work.
    std::unique_ptr<rt::AtomicFile> svgFile, jsonFile;
    try {
        if (!options.noSvg) {
            std::string svgPath = options.svgOut.value_or(std::filesystem::path(options.file).stem().string() + ".svg");
            svgFile = std::make_unique<rt::AtomicFile>(svgPath);
        }
        if (options.jsonOut) jsonFile = std::make_unique<rt::AtomicFile>(*options.jsonOut);
    } catch (const rt::OutputError& e) {
        std::fprintf(stderr, "g2d run: error: %s\n", e.what());
        return 1;
    }

    interp::RunFailure failure;
    try {
        Progress progress;
        interp::RunResult run = interp::runProgram(prog, std::move(params), options.seed, options.steps,
                                                   [&](long long s, const rt::Graph& g) { progress.update(s, g); },
                                                   &failure);
        const rt::DerivationResult& result = run.derivation;
        const rt::Graph& graph = run.graph;
        const interp::ProgramState& state = run.state;
        if (run.hitDefaultLimit)
            std::fprintf(stderr,
                         "%s: warning: stopped at the default limit of %lld steps; the grammar may not terminate "
                         "(set `limit N;` or pass --steps N)\n",
                         options.file.c_str(), interp::kDefaultStepLimit);

        if (svgFile) svgFile->commit(rt::writeSvg(interp::drawItems(graph, state), prog.svgDefs));
        if (jsonFile) {
            std::vector<std::pair<std::string, rt::Value>> meta = {
                {"grammar", std::filesystem::path(options.file).filename().string()},
                {"seed", static_cast<long long>(options.seed)},
                {"steps", result.steps},
                {"stopped", std::string(result.stopped == rt::StopReason::Terminal ? "terminal" : "step_limit")}};
            jsonFile->commit(rt::writeJson(graph, interp::jsonSchema(prog), meta));
        }
        if (options.stats)
            std::printf("{\"steps\": %lld, \"nodes\": %zu, \"edges\": %zu, \"seconds\": %s, \"seed\": %llu, "
                        "\"stopped\": \"%s\"}\n",
                        result.steps, graph.nodeCount(), graph.edgeCount(), rt::formatNumber(result.seconds).c_str(),
                        static_cast<unsigned long long>(options.seed),
                        result.stopped == rt::StopReason::Terminal ? "terminal" : "step_limit");
    } catch (const interp::EvalError& e) {
        reportRuntimeError(compiled, e, failure);
        return 1;
    } catch (const rt::RunawayError& e) {
        std::fprintf(stderr, "%s: error: %s\n", options.file.c_str(), e.what());
        return 1;
    } catch (const rt::OutputError& e) {
        std::fprintf(stderr, "g2d run: error: %s\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace g2d
