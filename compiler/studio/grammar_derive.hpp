#pragma once
// One run for the page: the text the page holds, compiled and derived by
// the interpreter with the run's own bounds (steps, elements, time), and
// its picture: the SVG (3D grammars drawn as `g2d run` draws them), and for
// a 3D grammar also the --view page's model.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "studio/api_reply.hpp"

namespace g2d::studio {

struct RunInput {
    std::string text;
    std::vector<std::string> defines;   // NAME=VALUE, as -D takes them
    std::uint64_t seed = 1;
    std::optional<long long> steps;     // the step limit (else the grammar's)
    double timeoutSeconds = 5;          // the time budget
};

// The request's JSON ({"text", "params": {name: value}, "seed", "steps",
// "timeout"}) as a RunInput, or why it cannot be.
std::optional<RunInput> runInputOf(const nlohmann::json& request, std::string& why);

// Compiles and derives `input` as the file `path`. `cancelled` is asked after
// every step; once it says yes, the run stops and the reply says "cancelled".
// Answers: 200 {"status": "ok", "svg", "model" (3D), "steps", "stopped",
// "elements": {nodes, edges, faces}, "ms", "diagnostics"}; 422 {"status":
// "invalid", "diagnostics"} for a grammar with errors; 422 {"status":
// "error", "message", "location"?, "stopped"?} for a run that failed;
// 409 {"status": "cancelled"}.
ApiReply deriveText(const std::string& path, const RunInput& input, const std::function<bool()>& cancelled);

}  // namespace g2d::studio
