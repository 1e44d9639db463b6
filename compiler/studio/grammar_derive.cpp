#include "studio/grammar_derive.hpp"

#include <chrono>
#include <filesystem>

#include "g2d/gltf_writer.hpp"
#include "g2d/graph.hpp"
#include "g2d/image_links.hpp"
#include "g2d/png_writer.hpp"
#include "g2d/run_outputs.hpp"
#include "g2d/view_page.hpp"
#include "studio/image_shelf.hpp"
#include "studio/param_specs.hpp"
#include "studio/studio_derivation.hpp"

namespace g2d::studio {

namespace {

using Clock = std::chrono::steady_clock;

rt::RunOutputs outputsOf(const StudioDerivation& run, const RunInput& input) {
    rt::RunOutputs outputs;
    outputs.svgOptions.viewBox = run.derived.canvas;
    outputs.grammarName = run.name;
    outputs.seed = input.seed;
    outputs.steps = run.derived.result.steps;
    outputs.stopped = run.stopped;
    return outputs;
}

// `compact`: alike lines joined into paths (the same picture, fewer elements for the page).
// `images`: the page's addresses for the image files the drawing links.
std::string svgOf(StudioDerivation& run, const RunInput& input, bool compact = false,
                  const std::function<std::string(const std::string&)>& images = {}) {
    rt::StringOut svg;
    rt::RunOutputs outputs = outputsOf(run, input);
    outputs.svg = &svg;
    outputs.svgOptions.compact = compact;
    outputs.svgOptions.imageHref = images;
    rt::writeRunOutputs(*run.grammar, outputs);
    return std::move(svg.text());
}

nlohmann::json elementsJson(const rt::Graph& graph) {
    return {{"nodes", graph.nodeCount()}, {"edges", graph.edgeCount()}, {"faces", graph.faceCount()}};
}

ApiReply outputError(const StudioDerivation& run, const std::exception& e) {
    return jsonReply(422, {{"status", "error"}, {"message", e.what()}, {"diagnostics", run.diagnostics}});
}

}  // namespace

ApiReply deriveText(const std::string& path, const RunInput& input, const std::function<bool()>& cancelled,
                    ImageShelf* images) {
    const auto started = Clock::now();
    auto run = deriveForPage(path, input, cancelled);
    if (run->failure) {
        // The panel keeps its controls while a value is wrong or the run fails.
        if (!run->failureBody || !run->grammar) return *run->failure;
        (*run->failureBody)["params"] = paramSpecsJson(run->grammar->params());
        return jsonReply(run->failure->status, *run->failureBody);
    }
    auto& grammar = *run->grammar;
    const bool space3d = grammar.jsonSchema().space3d;
    std::string svg, model, trace;
    try {
        // A 3D picture is drawn by the viewer from the model: its SVG would go unseen.
        if (space3d) {
            rt::ViewModel view = rt::viewModelOf(grammar.graph(), grammar.drawItems(), run->name, grammar.jsonSchema().kindNames);
            view.home = outputsOf(*run, input).view.toward;
            model = rt::viewModelJson(view);
        } else {
            std::function<std::string(const std::string&)> address;
            if (images) address = [images, &path](const std::string& href) { return images->hrefFor(path, href); };
            svg = svgOf(*run, input, true, address);
        }
        if (run->trace) trace = run->trace->json(run->name, input.seed, run->stopped);
    } catch (const std::exception& e) {
        return outputError(*run, e);
    }
    nlohmann::json reply = {
        {"status", "ok"},
        {"space", space3d ? "3d" : "2d"},
        {"params", paramSpecsJson(grammar.params())},
        {"steps", run->derived.result.steps},
        {"stopped", run->stopped},
        {"elements", elementsJson(grammar.graph())},
        {"ms", std::chrono::duration<double, std::milli>(Clock::now() - started).count()},
        {"diagnostics", run->diagnostics},
    };
    if (!space3d) reply["svg"] = std::move(svg);
    if (run->derived.hitDefaultLimit)
        reply["warning"] = "stopped at the default limit of " + std::to_string(rt::kDefaultStepLimit) +
                           " steps: the grammar may not terminate (set `limit N;`)";
    ApiReply out = jsonReply(200, reply);
    // The model and the trace are JSON already: spliced in, not parsed again.
    if (!model.empty()) out.body.insert(out.body.size() - 1, ",\"model\":" + model);
    if (!trace.empty()) out.body.insert(out.body.size() - 1, ",\"trace\":" + trace);
    return out;
}

ApiReply exportText(const std::string& path, const RunInput& input, ExportFormat format,
                    const std::function<bool()>& cancelled) {
    auto run = deriveForPage(path, input, cancelled);
    if (run->failure) return *run->failure;
    auto& grammar = *run->grammar;
    ApiReply out{200, "", exportMediaType(format)};
    try {
        rt::StringOut text, materials;
        rt::RunOutputs outputs = outputsOf(*run, input);
        switch (format) {
            case ExportFormat::Svg: out.body = svgOf(*run, input); break;
            case ExportFormat::Png: {
                rt::PngOptions png;
                png.baseFile = std::filesystem::absolute(path.empty() ? "untitled.g2d" : path).string();
                out.body = rt::renderPng(svgOf(*run, input), png);
                break;
            }
            case ExportFormat::Json: outputs.json = &text; break;
            case ExportFormat::Obj:
            case ExportFormat::Mtl:   // written together: the OBJ names its MTL, as `g2d run --obj NAME.obj` does
                outputs.obj = format == ExportFormat::Obj ? &text : &materials;
                outputs.mtl = format == ExportFormat::Obj ? &materials : &text;
                outputs.mtlName = std::filesystem::path(run->name).stem().string() + ".mtl";
                break;
            case ExportFormat::Gltf:
                out.body = rt::writeGltf(grammar.graph(), grammar.jsonSchema(),
                                         [&](rt::ElemClass cls, std::uint32_t id, rt::DrawItem& it) { grammar.drawItem(cls, id, it); },
                                         run->name);
                break;
        }
        if (outputs.json || outputs.obj) {
            rt::writeRunOutputs(grammar, outputs);
            out.body = std::move(text.text());
        }
    } catch (const std::exception& e) {
        return outputError(*run, e);
    }
    return out;
}

ApiReply seedSheet(const std::string& path, const RunInput& input, std::uint64_t first, int count, int width,
                   const std::function<bool()>& cancelled) {
    nlohmann::json sheet = nlohmann::json::array();
    for (int i = 0; i < count; ++i) {
        RunInput one = input;
        one.seed = first + std::uint64_t(i);
        one.trace = false;
        auto run = deriveForPage(path, one, cancelled);
        if (run->failure && run->failure->status == 409) return *run->failure;
        if (run->failure && !run->failureBody) return *run->failure;
        if (run->failure && (*run->failureBody)["status"] == "invalid") return *run->failure;   // no seed can do better
        nlohmann::json cell = {{"seed", one.seed}};
        if (run->failure) {
            cell["message"] = (*run->failureBody)["message"];
        } else {
            try {
                rt::PngOptions png;
                png.width = width;
                png.baseFile = std::filesystem::absolute(path.empty() ? "untitled.g2d" : path).string();
                cell["png"] = "data:image/png;base64," + rt::base64(rt::renderPng(svgOf(*run, one), png));
            } catch (const std::exception& e) {
                cell["message"] = e.what();
            }
            cell["steps"] = run->derived.result.steps;
            cell["stopped"] = run->stopped;
            cell["elements"] = elementsJson(run->grammar->graph());
        }
        sheet.push_back(std::move(cell));
    }
    return jsonReply(200, {{"status", "ok"}, {"sheet", std::move(sheet)}});
}

}  // namespace g2d::studio
