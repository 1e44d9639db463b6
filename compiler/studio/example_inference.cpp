#include "studio/example_inference.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <regex>

#include "infer/example_json.hpp"
#include "infer/example_picture.hpp"
#include "infer/example_svg.hpp"
#include "infer/grammar_report.hpp"
#include "infer/grammar_writer.hpp"
#include "infer/label_colours.hpp"
#include "infer/rule_sides.hpp"
#include "studio/grammar_derive.hpp"

namespace g2d::studio {

namespace {

constexpr int kMaxSize = 100000;   // target vertices: far beyond what a page can show

std::string areaName(const infer::LabelledExample& ex, int a) {
    return a < 0 ? std::string("none") : ex.shape.areas[static_cast<std::size_t>(a)].name;
}

// "NAME:12: …", "NAME:2:1: …" (the readers) or "NAME: line 12: …" (the labelling): the line and column.
nlohmann::json locationOf(const std::string& message, const std::string& name) {
    if (message.compare(0, name.size() + 1, name + ":") != 0) return nullptr;
    static const std::regex lineColumn(R"(^(\d+)(?::(\d+))?: )"), namedLine(R"(^ line (\d+))");
    const std::string rest = message.substr(name.size() + 1);
    std::smatch m;
    if (std::regex_search(rest, m, lineColumn)) {
        nlohmann::json at = {{"line", std::stoi(m[1])}};
        if (m[2].matched) at["column"] = std::stoi(m[2]);
        return at;
    }
    if (std::regex_search(rest, m, namedLine)) return {{"line", std::stoi(m[1])}};
    return nullptr;
}

nlohmann::json labelsJson(const infer::LabelledExample& ex) {
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t i = 0; i < ex.labels.size(); ++i) {
        const infer::EdgeLabel& l = ex.labels[i];
        out.push_back({{"id", "E" + std::to_string(i)},
                       {"brush", ex.shape.brushes[static_cast<std::size_t>(l.brush)].name},
                       {"direction", l.theta},
                       {"left", areaName(ex, l.left)},
                       {"right", areaName(ex, l.right)},
                       {"min_length", l.minLength},
                       {"max_length", l.maxLength},
                       {"count", l.edges.size()},
                       {"color", infer::edgeColour(ex, static_cast<int>(i))}});
    }
    return out;
}

nlohmann::json primitivesJson(const infer::LabelledExample& ex, const infer::InferredGrammar& g) {
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t k = 0; k < ex.primitives.size(); ++k) {
        const infer::Primitive& p = ex.primitives[k];
        nlohmann::json halves = nlohmann::json::array();
        for (int h : p.halves) {   // counter-clockwise from -180°, as the primitive keeps them
            const double d = ex.direction(h);
            halves.push_back({{"label", "E" + std::to_string(infer::edgeOfHalf(h))}, {"direction", d < 0 ? d + 360 : d},
                              {"out", !infer::barred(h)}});
        }
        out.push_back({{"id", "P" + std::to_string(k)},
                       {"halves", halves},
                       {"boundary", infer::boundaryString(ex, g.hierarchy[static_cast<std::size_t>(g.primitiveGraph[k])].graph.boundary)},
                       {"count", p.vertices.size()},
                       {"color", infer::primitiveColour(static_cast<int>(k))},
                       {"svg", infer::primitiveSvg(ex, static_cast<int>(k))}});
    }
    return out;
}

nlohmann::json rulesJson(const infer::LabelledExample& ex, const infer::InferredGrammar& g) {
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t r = 0; r < g.rules.size(); ++r) {
        const infer::InferredRule& rule = g.rules[r];
        const infer::RuleSides sides = infer::ruleSides(ex, g, rule);
        nlohmann::json right = nlohmann::json::array();
        for (const infer::RulePiece& piece : rule.right) right.push_back(infer::graphText(ex, g, piece.graph));
        out.push_back({{"index", r},
                       {"starter", rule.starter()},
                       {"restructures", rule.restructures},
                       {"left", infer::graphText(ex, g, rule.left)},
                       {"right", right},
                       {"left_svg", infer::ruleSideSvg(ex, sides.left)},
                       {"right_svg", infer::ruleSideSvg(ex, sides.right)}});
    }
    return out;
}

nlohmann::json countsJson(const infer::InferenceCounts& c) {
    return {{"vertices", c.vertices}, {"edges", c.edges},   {"labels", c.labels},       {"primitives", c.primitives},
            {"graphs", c.graphs},     {"pruned", c.pruned}, {"left_over", c.leftOver}, {"rules", c.rules},
            {"starters", c.starters}};
}

ApiReply cancelledReply() { return jsonReply(409, {{"status", "cancelled"}}); }

}  // namespace

std::optional<InferInput> inferInputOf(const nlohmann::json& request, std::string& why) {
    InferInput input;
    if (!request.is_object() || !request.contains("example") || !request["example"].is_string()) {
        why = "expected an object with the example's text as \"example\"";
        return std::nullopt;
    }
    input.example = request["example"].get<std::string>();
    const std::string format = request.contains("format") && request["format"].is_string() ? request["format"].get<std::string>() : "";
    if (format != "svg" && format != "json") {
        why = "\"format\" must be \"svg\" or \"json\"";
        return std::nullopt;
    }
    input.svg = format == "svg";
    input.name = "example." + format;
    if (request.contains("name")) {
        if (!request["name"].is_string()) {
            why = "\"name\" must be a string (the example's file name)";
            return std::nullopt;
        }
        // Only for messages and the grammar's header comment: the last part of whatever the page
        // sends, without control characters (a line break would end the comment).
        std::string name = std::filesystem::path(request["name"].get<std::string>()).filename().string();
        for (char& c : name)
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
        if (!name.empty()) input.name = name;
    }
    if (request.contains("size") && !request["size"].is_null()) {
        if (!request["size"].is_number_unsigned() || request["size"].get<std::uint64_t>() < 1 || request["size"].get<std::uint64_t>() > kMaxSize) {
            why = "\"size\" (the target number of vertices) must be a whole number from 1 to " + std::to_string(kMaxSize);
            return std::nullopt;
        }
        input.size = request["size"].get<int>();
    }
    if (request.contains("connected")) {
        if (!request["connected"].is_boolean()) {
            why = "\"connected\" must be true or false";
            return std::nullopt;
        }
        input.connected = request["connected"].get<bool>();
    }
    // The seed and the generation's time budget as /api/run reads them (one set of rules and messages).
    nlohmann::json run = {{"text", ""}, {"timeout", input.timeoutSeconds}};
    for (const char* key : {"seed", "timeout"})
        if (request.contains(key)) run[key] = request[key];
    const auto runInput = runInputOf(run, why);
    if (!runInput) return std::nullopt;
    input.seed = runInput->seed;
    input.timeoutSeconds = runInput->timeoutSeconds;
    return input;
}

ApiReply inferExample(const std::string& path, const InferInput& input, const std::function<bool()>& cancelled) {
    if (cancelled()) return cancelledReply();
    const auto started = std::chrono::steady_clock::now();
    // The steps of runInfer (compiler/driver/infer_command.cpp), with its defaults.
    infer::LabelledExample ex;
    infer::InferredGrammar inferred;
    std::string grammar;
    try {
        ex = infer::labelExample(input.svg ? infer::readExampleSvg(input.example, input.name) : infer::readExampleJson(input.example, input.name));
        inferred = infer::inferGrammar(ex);
        infer::WriterOptions writer;
        writer.source = input.name;
        writer.targetVertices = input.size;
        writer.connected = input.connected;
        grammar = infer::writeGrammar(ex, inferred, writer);
    } catch (const infer::InputError& e) {
        nlohmann::json reply = {{"status", "error"}, {"message", e.message}};
        if (auto at = locationOf(e.message, input.name); !at.is_null()) reply["location"] = at;
        return jsonReply(422, reply);
    }
    if (cancelled()) return cancelledReply();   // inference has no step to stop at: looked at before and after

    const infer::InferenceCounts counts = infer::countInference(ex, inferred);
    nlohmann::json reply = {{"status", "ok"},
                            {"name", ex.shape.name},
                            {"counts", countsJson(counts)},
                            {"labels", labelsJson(ex)},
                            {"primitives", primitivesJson(ex, inferred)},
                            {"rules", rulesJson(ex, inferred)},
                            {"report", infer::describeGrammar(ex, inferred)},
                            {"grammar", grammar},
                            {"example_svg", infer::exampleSvg(ex)},
                            {"seed", input.seed}};
    if (counts.leftOver > 0)
        reply["warning"] = "the grammar may be incomplete: " + std::to_string(counts.leftOver) +
                           " graphs were left over at the hierarchy's limits (§5.7)";

    // One output, derived exactly as /api/run derives the same text and seed.
    RunInput run;
    run.text = grammar;
    run.seed = input.seed;
    run.timeoutSeconds = input.timeoutSeconds;
    const ApiReply generated = deriveText(path, run, cancelled);
    if (generated.status == 409) return generated;
    const nlohmann::json result = nlohmann::json::parse(generated.body, nullptr, false);
    if (generated.status == 200 && result.is_object()) {
        reply["generated_svg"] = result["svg"];
        reply["generated"] = {{"steps", result["steps"]}, {"stopped", result["stopped"]}, {"elements", result["elements"]}, {"ms", result["ms"]}};
    } else {   // the inference stands; the page shows why there is no picture
        reply["generated_svg"] = nullptr;
        reply["generate_error"] = result.is_object() && result.contains("message") ? result["message"].get<std::string>()
                                                                                  : std::string("the written grammar did not compile");
    }
    reply["ms"] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    return jsonReply(200, reply);
}

}  // namespace g2d::studio
