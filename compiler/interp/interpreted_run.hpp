#pragma once
// The interpreter as a back end of the shared run driver.
#include <memory>

#include "diag/source.hpp"
#include "g2d/grammar_run.hpp"
#include "interp/interpreted_rules.hpp"

namespace g2d::interp {

class InterpretedRun : public rt::GrammarRun {
public:
    // `sources` (for error locations) may be null.
    InterpretedRun(const ir::Program& prog, const SourceManager* sources);

    const std::vector<rt::ParamSpec>& params() const override { return params_; }
    void start(const std::vector<rt::Value>& params, rt::Rng& rng) override;
    std::optional<long long> stepLimit() override;
    std::map<long long, long long> priorityLimits() override;
    std::map<std::size_t, long long> ruleLimits() override;
    std::vector<long long> repeatCounts() override;
    std::optional<rt::ViewBox> canvas() override;
    rt::Graph& graph() override { return graph_; }
    rt::RuleSet& rules() override { return *rules_; }
    void drawItem(rt::ElemClass cls, std::uint32_t id, rt::DrawItem& out) override;
    const std::vector<std::string>& svgDefs() const override { return prog_.svgDefs; }
    const rt::JsonSchema& jsonSchema() const override { return schema_; }
    rt::Value attribute(rt::ElemClass cls, std::uint32_t id, int attr) const override;
    std::optional<rt::SourceLocation> locate(const std::exception& e) const override;
    std::string currentRule() const override;

    const ProgramState& state() const { return state_; }

private:
    const ir::Program& prog_;
    std::shared_ptr<const lower::LoweredProgram> lowered_;
    const SourceManager* sources_;
    std::vector<rt::ParamSpec> params_;
    rt::JsonSchema schema_;
    ProgramState state_;
    rt::Graph graph_{{}};
    std::unique_ptr<InterpretedRules> rules_;
};

std::vector<rt::ParamSpec> paramSpecs(const ir::Program& prog);

}  // namespace g2d::interp
