#pragma once
// Infer mode: an example the page sends (SVG or the author's JSON) goes the
// way of `g2d infer -o`: read, labelled, inferred, written as a grammar (the
// same library calls); then the written grammar is derived once as /api/run
// derives a text, so the page shows what it generates.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "studio/api_reply.hpp"

namespace g2d::studio {

struct InferInput {
    std::string example;            // the file's text
    bool svg = false;               // else the author's JSON
    std::string name;               // the file's name, for messages and the grammar's header (never opened)
    std::uint64_t seed = 1;
    int size = 0;                   // the written grammar's target vertices, as --size (0: the writer's default)
    bool connected = false;         // as --connected
    double timeoutSeconds = 10;     // the generation's time budget
};

// The request's JSON ({"example", "format": "svg" | "json", "name"?, "seed"?,
// "size"?, "connected"?, "timeout"?}) as an InferInput, or why it cannot be.
std::optional<InferInput> inferInputOf(const nlohmann::json& request, std::string& why);

// Answers 200 {"status": "ok", "name", "counts", "labels", "primitives",
// "rules", "report", "warning"?, "grammar", "example_svg", "generated_svg"
// (null when the generation failed: "generate_error" says why), "generated":
// {steps, stopped, elements, ms}, "seed", "ms" (all of it)}; 422 {"status": "error",
// "message", "location"?} for an example the readers refuse; 409
// {"status": "cancelled"} once `cancelled` says yes. `path` is the studio's
// file, as /api/run compiles a text as that file.
ApiReply inferExample(const std::string& path, const InferInput& input, const std::function<bool()>& cancelled);

}  // namespace g2d::studio
