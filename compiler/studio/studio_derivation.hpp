#pragma once
// One derivation for the page: the text compiled and derived by the
// interpreter with the run's own bounds (steps, elements, time), kept with
// what the outputs need. `failure` holds the answer when it did not finish.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "front/compile.hpp"
#include "g2d/derive_grammar.hpp"
#include "g2d/trace.hpp"
#include "interp/interpreted_run.hpp"
#include "studio/api_reply.hpp"
#include "studio/run_request.hpp"

namespace g2d::studio {

struct StudioDerivation {
    CompileResult compiled;
    std::unique_ptr<interp::InterpretedRun> grammar;
    std::unique_ptr<rt::TraceRecorder> trace;   // when the input asks for it
    rt::DerivedRun derived;
    std::string stopped;                        // as the JSON output's "stopped" says
    std::string name;                           // the file's name, for the outputs
    nlohmann::json diagnostics;                 // the checker's, even when it compiled
    std::optional<ApiReply> failure;            // 422 invalid/error, or 409 cancelled
    std::optional<nlohmann::json> failureBody;  // the failure's JSON, for answers that add to it
};

// Thrown from the step observer when a newer request replaced this run.
struct RunCancelled : std::runtime_error {
    RunCancelled() : std::runtime_error("cancelled by a newer run") {}
};

ApiReply cancelledReply();

// Compiles `input.text` as the file `path` and derives it. `cancelled` is
// asked after every step; once it says yes, the run stops with a 409.
std::unique_ptr<StudioDerivation> deriveForPage(const std::string& path, const RunInput& input,
                                                const std::function<bool()>& cancelled);

}  // namespace g2d::studio
