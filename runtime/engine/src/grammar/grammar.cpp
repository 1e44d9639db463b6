#include "g2d/grammar.hpp"

#include <filesystem>
#include <stdexcept>

#include "g2d/derive_grammar.hpp"
#include "g2d/graph.hpp"
#include "g2d/run_outputs.hpp"

namespace g2d {

Grammar::Grammar(std::unique_ptr<rt::GrammarRun> run, std::string fileName)
    : run_(std::move(run)), fileName_(std::move(fileName)) {
    for (const auto& p : run_->params()) params_.push_back(p.defaultValue);
}

std::vector<std::string> Grammar::parameterNames() const {
    std::vector<std::string> out;
    for (const auto& p : run_->params()) out.push_back(p.name);
    return out;
}

void Grammar::set(const std::string& name, const std::string& value) {
    const auto& specs = run_->params();
    for (std::size_t i = 0; i < specs.size(); ++i) {
        if (specs[i].name != name) continue;
        std::string why;
        auto v = rt::parameterValue(specs[i], value, why);
        if (!v) throw std::invalid_argument(why);
        params_[i] = std::move(*v);
        return;
    }
    throw std::invalid_argument("the grammar has no parameter `" + name + "`");
}

rt::DerivationResult Grammar::derive(std::optional<long long> steps) {
    try {
        rt::RunSettings settings;
        settings.steps = steps;
        rt::DerivedRun derived;
        rt::deriveGrammar(*run_, params_, seed_, settings, derived);
        last_ = derived.result;
    } catch (const rt::RunawayError&) {
        throw;
    } catch (const std::exception& e) {
        const std::string rule = run_->currentRule();
        const std::string where = rule.empty() ? "" : " (in rule `" + rule + "`)";
        if (auto at = run_->locate(e)) throw std::runtime_error(rt::renderLocatedError(*at, e.what() + where));
        throw std::runtime_error(e.what() + where);
    }
    return last_;
}

GraphView Grammar::view() const { return GraphView(run_->graph(), run_->jsonSchema().kindNames); }

const rt::Graph& Grammar::graph() const { return run_->graph(); }

rt::Value Grammar::attribute(rt::ElemClass cls, std::uint32_t id, const std::string& name) const {
    const int kind = run_->graph().kindOf(cls, id);
    const auto& names = run_->jsonSchema().attrNames.at(static_cast<std::size_t>(kind));
    for (std::size_t a = 0; a < names.size(); ++a)
        if (names[a] == name) return run_->attribute(cls, id, static_cast<int>(a));
    throw std::invalid_argument("kind `" + run_->jsonSchema().kindNames.at(static_cast<std::size_t>(kind)) +
                                "` has no attribute `" + name + "`");
}

namespace {

// One output of the last derivation, as g2d run writes it without options
// (the SVG's viewBox: the canvas); `sink` says which. An OBJ names its MTL
// `mtlName` when one is given; the MTL is written beside an OBJ (dropped).
std::string lastOutput(rt::GrammarRun& run, const std::string& fileName, std::uint64_t seed, const rt::DerivationResult& last,
                       rt::TextOut* rt::RunOutputs::*sink, const std::string& mtlName = {}) {
    rt::StringOut text, dropped;
    rt::RunOutputs out;
    out.grammarName = std::filesystem::path(fileName).filename().string();
    out.seed = seed;
    out.steps = last.steps;
    out.stopped = rt::stopName(last.stopped);
    out.svgOptions.viewBox = run.canvas();
    if (!mtlName.empty() || sink == &rt::RunOutputs::mtl) {
        out.obj = &dropped;
        out.mtl = &dropped;
        out.mtlName = mtlName;
    }
    out.*sink = &text;
    rt::writeRunOutputs(run, out);
    return std::move(text.text());
}

}  // namespace

std::string Grammar::svg() { return lastOutput(*run_, fileName_, seed_, last_, &rt::RunOutputs::svg); }
std::string Grammar::json() { return lastOutput(*run_, fileName_, seed_, last_, &rt::RunOutputs::json); }
std::string Grammar::obj(const std::string& mtlName) {
    return lastOutput(*run_, fileName_, seed_, last_, &rt::RunOutputs::obj, mtlName);
}
std::string Grammar::mtl() { return lastOutput(*run_, fileName_, seed_, last_, &rt::RunOutputs::mtl); }

}  // namespace g2d
