#include "studio/run_request.hpp"

#include "studio/api_reply.hpp"

namespace g2d::studio {

namespace {

constexpr double kMaxTimeoutSeconds = 60;
constexpr std::uint64_t kMaxSteps = std::uint64_t{1} << 62;   // a long long, whatever the client sends

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

struct FormatName {
    ExportFormat format;
    const char* name;
    const char* mediaType;
};
// Types cpp-httplib does not compress (api_reply.hpp says why).
constexpr FormatName kFormats[] = {
    {ExportFormat::Svg, "svg", "image/svg+xml; charset=utf-8"},   {ExportFormat::Png, "png", "image/png"},
    {ExportFormat::Json, "json", kJsonType},                      {ExportFormat::Obj, "obj", "model/obj"},
    {ExportFormat::Mtl, "mtl", "model/mtl"},                      {ExportFormat::Gltf, "glb", "model/gltf-binary"},
};

const FormatName& formatName(ExportFormat format) {
    for (const auto& f : kFormats)
        if (f.format == format) return f;
    return kFormats[0];
}

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
    if (request.contains("trace")) {
        if (!request["trace"].is_boolean()) {
            why = "\"trace\" must be true or false";
            return std::nullopt;
        }
        input.trace = request["trace"].get<bool>();
    }
    return input;
}

std::optional<ExportFormat> exportFormatOf(const std::string& name) {
    for (const auto& f : kFormats)
        if (name == f.name) return f.format;
    return std::nullopt;
}

const char* exportExtension(ExportFormat format) { return formatName(format).name; }
const char* exportMediaType(ExportFormat format) { return formatName(format).mediaType; }

}  // namespace g2d::studio
