#include "interp/interpreted_run.hpp"

#include "g2d/command_list.hpp"
#include "g2d/ops.hpp"
#include "interp/drawing.hpp"

namespace g2d::interp {

std::vector<rt::ParamSpec> paramSpecs(const ir::Program& prog) {
    std::vector<rt::ParamSpec> out;
    for (const auto& p : prog.params) {
        rt::ParamSpec s;
        s.name = p.name;
        s.typeName = ir::typeName(p.type, prog);
        switch (p.type.kind) {
        case ir::TypeKind::Int: s.type = rt::ParamType::Int; break;
        case ir::TypeKind::Float: s.type = rt::ParamType::Float; break;
        case ir::TypeKind::Bool: s.type = rt::ParamType::Bool; break;
        case ir::TypeKind::Vec2: s.type = rt::ParamType::Vec2; break;
        case ir::TypeKind::Vec3: s.type = rt::ParamType::Vec3; break;
        case ir::TypeKind::Enum:
            s.type = rt::ParamType::Enum;
            s.enumId = p.type.enumId;
            s.enumValues = prog.enums[p.type.enumId].values;
            break;
        default: s.type = rt::ParamType::String; break;
        }
        s.defaultValue = fromLiteral(p.defaultValue);
        s.min = p.min;
        s.max = p.max;
        s.step = p.step;
        out.push_back(std::move(s));
    }
    return out;
}

InterpretedRun::InterpretedRun(const ir::Program& prog, const SourceManager* sources)
    : prog_(prog), lowered_(std::make_shared<const lower::LoweredProgram>(lower::lowerProgram(prog))), sources_(sources),
      params_(paramSpecs(prog)), schema_(interp::jsonSchema(prog)) {}

void InterpretedRun::start(const std::vector<rt::Value>& params, rt::Rng& rng) {
    graph_ = startRun(lowered_, params, rng, state_);
    rules_ = std::make_unique<InterpretedRules>(state_);
}

std::optional<long long> InterpretedRun::stepLimit() {
    if (!prog_.stepLimit) return std::nullopt;
    EvalFrame f = state_.frame(nullptr);
    return std::get<long long>(evaluate(*prog_.stepLimit, f));
}

std::map<long long, long long> InterpretedRun::priorityLimits() {
    std::map<long long, long long> out;
    EvalFrame f = state_.frame(nullptr);
    for (const auto& [prio, cfg] : prog_.priorities)
        if (cfg.limit) out[prio] = std::get<long long>(evaluate(*cfg.limit, f));
    return out;
}

std::map<std::size_t, long long> InterpretedRun::ruleLimits() {
    std::map<std::size_t, long long> out;
    EvalFrame f = state_.frame(nullptr);
    for (std::size_t r = 0; r < prog_.rules.size(); ++r)
        if (prog_.rules[r].limit) out[r] = std::get<long long>(evaluate(*prog_.rules[r].limit, f));
    return out;
}

std::vector<long long> InterpretedRun::repeatCounts() {
    std::vector<long long> out;
    EvalFrame f = state_.frame(nullptr);
    for (const ir::Expr& count : prog_.repeatCounts) {
        try {
            out.push_back(rt::checkedRepeatCount(std::get<long long>(evaluate(count, f))));
        } catch (const rt::OpError& e) {
            throw EvalError(count.span, e.what());
        }
    }
    return out;
}

std::optional<rt::ViewBox> InterpretedRun::canvas() {
    if (!prog_.canvas) return std::nullopt;
    const ir::Canvas& c = *prog_.canvas;
    EvalFrame f = state_.frame(nullptr);
    const rt::vec2 lower = std::get<rt::vec2>(evaluate(c.lower, f));
    const rt::vec2 upper = std::get<rt::vec2>(evaluate(c.upper, f));
    try {
        return rt::checkedCanvas(lower, upper);
    } catch (const rt::OpError& e) {
        throw EvalError(c.span, e.what());
    }
}

void InterpretedRun::drawItem(rt::ElemClass cls, std::uint32_t id, rt::DrawItem& out) {
    interp::drawItem(graph_, state_, schema_.enumValueNames, cls, id, out);
}

rt::Value InterpretedRun::attribute(rt::ElemClass cls, std::uint32_t id, int attr) const {
    return graph_.attrOf(cls, id, attr);
}

std::optional<rt::SourceLocation> InterpretedRun::locate(const std::exception& e) const {
    const auto* err = dynamic_cast<const EvalError*>(&e);
    if (!err || !sources_ || !err->span.valid() || err->span.file >= sources_->size()) return std::nullopt;
    rt::SourceLocation at;
    at.file = sources_->file(err->span.file).path;
    at.line = err->span.line;
    at.col = err->span.col;
    at.endCol = err->span.endLine == err->span.line ? err->span.endCol : 0;
    at.lineText = sources_->lineText(err->span.file, err->span.line);
    return at;
}

std::string InterpretedRun::currentRule() const {
    return rules_ && rules_->currentRule() ? rules_->currentRule()->name : "";
}

}  // namespace g2d::interp
