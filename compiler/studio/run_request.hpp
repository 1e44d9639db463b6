#pragma once
// What the page asks of a run, read from its JSON: the text, parameter
// values, seed, step limit, time budget, and which outputs it wants.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace g2d::studio {

// A file the page can download, made as `g2d run` makes it.
enum class ExportFormat { Svg, Png, Json, Obj, Mtl, Gltf };

struct RunInput {
    std::string text;
    std::vector<std::string> defines;   // NAME=VALUE, as -D takes them
    std::uint64_t seed = 1;
    std::optional<long long> steps;     // the step limit (else the grammar's)
    double timeoutSeconds = 5;          // the time budget
    bool trace = false;                 // the derivation step by step too (the player)
};

// The request's JSON ({"text", "params": {name: value}, "seed", "steps",
// "timeout", "trace"}) as a RunInput, or why it cannot be.
std::optional<RunInput> runInputOf(const nlohmann::json& request, std::string& why);

// "svg", "png", "json", "obj", "mtl", "glb".
std::optional<ExportFormat> exportFormatOf(const std::string& name);
const char* exportExtension(ExportFormat format);
const char* exportMediaType(ExportFormat format);

}  // namespace g2d::studio
