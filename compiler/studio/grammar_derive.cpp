#include "studio/grammar_derive.hpp"

#include <chrono>
#include <filesystem>

#include "g2d/derive_grammar.hpp"
#include "g2d/graph.hpp"
#include "g2d/parameter_values.hpp"
#include "g2d/projection.hpp"
#include "g2d/run_outputs.hpp"
#include "g2d/view_page.hpp"
#include "interp/interpreted_run.hpp"
#include "studio/grammar_check.hpp"

namespace g2d::studio {

namespace {

constexpr double kMaxTimeoutSeconds = 60;
constexpr std::uint64_t kMaxSteps = std::uint64_t{1} << 62;   // a long long, whatever the client sends

// Thrown from the step observer when a newer request replaced this run.
struct RunCancelled : std::runtime_error {
    RunCancelled() : std::runtime_error("cancelled by a newer run") {}
};

// A parameter value as -D would spell it.
std::optional<std::string> defineText(const nlohmann::json& v) {
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    if (v.is_number()) return v.dump();
    if (v.is_array()) {
        std::string out;
        for (const auto& x : v) {
            if (!x.is_number()) return std::nullopt;
            out += (out.empty() ? "" : ",") + x.dump();
        }
        return out;
    }
    return std::nullopt;
}

nlohmann::json locationJson(const rt::SourceLocation& at) {
    return {{"file", at.file}, {"line", at.line}, {"column", at.col}, {"end_column", at.endCol}};
}

ApiReply cancelledReply() { return jsonReply(409, {{"status", "cancelled"}}); }

}  // namespace

std::optional<RunInput> runInputOf(const nlohmann::json& request, std::string& why) {
    RunInput input;
    if (!request.is_object() || !request.contains("text") || !request["text"].is_string()) {
        why = "expected an object with the grammar as \"text\"";
        return std::nullopt;
    }
    input.text = request["text"].get<std::string>();
    if (request.contains("params")) {
        if (!request["params"].is_object()) {
            why = "\"params\" must be an object of parameter values";
            return std::nullopt;
        }
        for (const auto& [name, value] : request["params"].items()) {
            auto text = defineText(value);
            if (!text) {
                why = "parameter `" + name + "`: give a number, a string, true/false or a list of numbers";
                return std::nullopt;
            }
            input.defines.push_back(name + "=" + *text);
        }
    }
    if (request.contains("seed")) {
        if (!request["seed"].is_number_unsigned()) {
            why = "\"seed\" must be a whole number, 0 or more";
            return std::nullopt;
        }
        input.seed = request["seed"].get<std::uint64_t>();
    }
    if (request.contains("steps") && !request["steps"].is_null()) {
        if (!request["steps"].is_number_unsigned() || request["steps"].get<std::uint64_t>() > kMaxSteps) {
            why = "\"steps\" must be a whole number from 0 to " + std::to_string(kMaxSteps);
            return std::nullopt;
        }
        input.steps = request["steps"].get<long long>();
    }
    if (request.contains("timeout")) {
        const auto& t = request["timeout"];
        if (!t.is_number() || !(t.get<double>() > 0) || t.get<double>() > kMaxTimeoutSeconds) {
            why = "\"timeout\" must be a number of seconds above 0, at most " + std::to_string(int(kMaxTimeoutSeconds));
            return std::nullopt;
        }
        input.timeoutSeconds = t.get<double>();
    }
    return input;
}

ApiReply deriveText(const std::string& path, const RunInput& input, const std::function<bool()>& cancelled) {
    if (cancelled()) return cancelledReply();
    const auto started = std::chrono::steady_clock::now();
    CompileResult compiled = compileText(path, input.text);
    nlohmann::json diagnostics = diagnosticsJson(compiled);
    if (!compiled.program) return jsonReply(422, {{"status", "invalid"}, {"diagnostics", diagnostics}});
    interp::InterpretedRun grammar(*compiled.program, &compiled.sources);

    std::vector<rt::Value> params;
    if (std::string why = rt::parameterValues(grammar.params(), input.defines, params); !why.empty())
        return errorReply(422, why);
    rt::RunSettings settings;
    settings.steps = input.steps;
    settings.timeoutSeconds = input.timeoutSeconds;
    rt::DerivedRun derived;
    rt::RunProgress progress;
    std::string stopped;
    try {
        rt::deriveGrammar(grammar, params, input.seed, settings, derived,
                          [&](long long, const rt::Graph&) {
                              if (cancelled()) throw RunCancelled();
                          },
                          &progress);
        stopped = derived.hitDefaultLimit ? "default_step_limit" : rt::stopName(derived.result.stopped);
    } catch (const std::exception& e) {
        if (cancelled()) return cancelledReply();
        nlohmann::json reply = {{"status", "error"}, {"diagnostics", diagnostics}};
        if (const auto* runaway = dynamic_cast<const rt::RunawayError*>(&e)) {
            reply["message"] = e.what();
            reply["stopped"] = runaway->bound();
        } else {
            const std::string rule = grammar.currentRule();
            reply["message"] = e.what() + (rule.empty() ? std::string(" (before the first step)")
                                                        : " (in rule `" + rule + "`, step " + std::to_string(progress.step + 1) + ")");
            if (auto at = grammar.locate(e)) reply["location"] = locationJson(*at);
        }
        return jsonReply(422, reply);
    }

    const rt::Graph& graph = grammar.graph();
    const std::string name = std::filesystem::path(path.empty() ? "untitled.g2d" : path).filename().string();
    std::string model;
    rt::StringOut svg;
    try {
        rt::RunOutputs outputs;
        outputs.svg = &svg;
        outputs.svgOptions.viewBox = derived.canvas;
        outputs.grammarName = name;
        outputs.seed = input.seed;
        outputs.steps = derived.result.steps;
        outputs.stopped = stopped;
        rt::writeRunOutputs(grammar, outputs);
        if (grammar.jsonSchema().space3d) {
            rt::ViewModel view = rt::viewModelOf(graph, grammar.drawItems(), name, grammar.jsonSchema().kindNames);
            view.home = outputs.view.toward;
            model = rt::viewModelJson(view);
        }
    } catch (const std::exception& e) {
        return jsonReply(422, {{"status", "error"}, {"message", e.what()}, {"diagnostics", diagnostics}});
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    nlohmann::json reply = {
        {"status", "ok"},
        {"space", grammar.jsonSchema().space3d ? "3d" : "2d"},
        {"svg", std::move(svg.text())},
        {"steps", derived.result.steps},
        {"stopped", stopped},
        {"elements", {{"nodes", graph.nodeCount()}, {"edges", graph.edgeCount()}, {"faces", graph.faceCount()}}},
        {"ms", ms},
        {"diagnostics", diagnostics},
    };
    if (derived.hitDefaultLimit)
        reply["warning"] = "stopped at the default limit of " + std::to_string(rt::kDefaultStepLimit) +
                           " steps: the grammar may not terminate (set `limit N;`)";
    ApiReply out = jsonReply(200, reply);
    // The model is already JSON (the --view page's own): spliced in, not parsed again.
    if (!model.empty()) out.body.insert(out.body.size() - 1, ",\"model\":" + model);
    return out;
}

}  // namespace g2d::studio
