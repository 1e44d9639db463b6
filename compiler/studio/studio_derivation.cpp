#include "studio/studio_derivation.hpp"

#include <filesystem>

#include "g2d/graph.hpp"
#include "g2d/parameter_values.hpp"
#include "g2d/run_outputs.hpp"
#include "studio/grammar_check.hpp"

namespace g2d::studio {

namespace {

nlohmann::json locationJson(const rt::SourceLocation& at) {
    return {{"file", at.file}, {"line", at.line}, {"column", at.col}, {"end_column", at.endCol}};
}

}  // namespace

ApiReply cancelledReply() { return jsonReply(409, {{"status", "cancelled"}}); }

namespace {

void fail(StudioDerivation& run, nlohmann::json body) {
    run.failure = jsonReply(422, body);
    run.failureBody = std::move(body);
}

}  // namespace

std::unique_ptr<StudioDerivation> deriveForPage(const std::string& path, const RunInput& input,
                                                const std::function<bool()>& cancelled) {
    auto run = std::make_unique<StudioDerivation>();
    if (cancelled()) {
        run->failure = cancelledReply();
        return run;
    }
    run->compiled = compileText(path, input.text);
    run->diagnostics = diagnosticsJson(run->compiled);
    if (!run->compiled.program) {
        fail(*run, {{"status", "invalid"}, {"diagnostics", run->diagnostics}});
        return run;
    }
    run->grammar = std::make_unique<interp::InterpretedRun>(*run->compiled.program, &run->compiled.sources);
    auto& grammar = *run->grammar;
    run->name = std::filesystem::path(path.empty() ? "untitled.g2d" : path).filename().string();

    std::vector<rt::Value> params;
    if (std::string why = rt::parameterValues(grammar.params(), input.defines, params); !why.empty()) {
        fail(*run, {{"status", "error"}, {"message", why}, {"diagnostics", run->diagnostics}});
        return run;
    }
    rt::RunSettings settings;
    settings.steps = input.steps;
    settings.timeoutSeconds = input.timeoutSeconds;
    if (input.trace) run->trace = std::make_unique<rt::TraceRecorder>(grammar);
    rt::RunProgress progress;
    try {
        rt::deriveGrammar(grammar, params, input.seed, settings, run->derived,
                          [&](long long, const rt::Graph&) {
                              if (cancelled()) throw RunCancelled();
                          },
                          &progress, run->trace.get());
        run->stopped = run->derived.hitDefaultLimit ? "default_step_limit" : rt::stopName(run->derived.result.stopped);
    } catch (const std::exception& e) {
        if (cancelled()) {
            run->failure = cancelledReply();
            return run;
        }
        nlohmann::json reply = {{"status", "error"}, {"diagnostics", run->diagnostics}};
        if (const auto* runaway = dynamic_cast<const rt::RunawayError*>(&e)) {
            reply["message"] = e.what();
            reply["stopped"] = runaway->bound();
        } else {
            const std::string rule = grammar.currentRule();
            reply["message"] = e.what() + (rule.empty() ? std::string(" (before the first step)")
                                                        : " (in rule `" + rule + "`, step " + std::to_string(progress.step + 1) + ")");
            if (auto at = grammar.locate(e)) reply["location"] = locationJson(*at);
        }
        fail(*run, std::move(reply));
        return run;
    }
    return run;
}

}  // namespace g2d::studio
