#include "interp/program_state.hpp"

#include "interp/rewrite_executor.hpp"

namespace g2d::interp {

EvalFrame ProgramState::frame(rt::Rng* rng) const {
    EvalFrame f;
    f.prog = &program();
    f.params = &params;
    f.consts = &consts;
    f.rng = rng;
    return f;
}

std::vector<rt::KindInfo> kindInfos(const ir::Program& prog) {
    std::vector<rt::KindInfo> out;
    for (const auto& k : prog.kinds) out.push_back(rt::KindInfo{k.cls, k.directed});
    return out;
}

rt::Graph startRun(const ir::Program& prog, std::vector<rt::Value> params, rt::Rng& rng, ProgramState& st) {
    return startRun(std::make_shared<const lower::LoweredProgram>(lower::lowerProgram(prog)), std::move(params), rng, st);
}

rt::Graph startRun(std::shared_ptr<const lower::LoweredProgram> lowered, std::vector<rt::Value> params, rt::Rng& rng,
                   ProgramState& st) {
    const ir::Program& prog = *lowered->ir;
    const lower::StartProgram& start = lowered->start;
    st = ProgramState{};
    st.lowered = std::move(lowered);
    st.params = std::move(params);
    st.consts.resize(prog.consts.size());
    for (const auto& k : prog.kinds) st.kindDefaults.emplace_back(k.attrs.size());
    for (const auto& op : start.init) {
        EvalFrame f = st.frame(&rng);
        std::visit(lower::Overloaded{
                       [&](const lower::InitConst& o) {
                           st.consts[o.index] = o.decl->folded ? fromLiteral(*o.decl->folded) : evaluate(o.decl->value, f);
                       },
                       [&](const lower::InitDefault& o) { st.kindDefaults[o.kind][o.attr] = evaluate(*o.value, f); },
                   },
                   op);
    }
    rt::Graph g(kindInfos(prog), prog.styleProps);
    for (std::size_t k = 0; k < st.kindDefaults.size(); ++k) g.setKindDefaults(static_cast<int>(k), st.kindDefaults[k]);
    EvalFrame f = st.frame(&rng);
    std::vector<rt::Value> registers(start.axiom.registers.size());
    RewriteExecutor axiom;
    std::vector<interp::LoopValues> loops;   // the axiom has none
    axiom.prepare(start.axiom, rt::Match{}, g, f, registers, loops);
    axiom.commit(start.axiom, rt::Match{}, registers, loops, g, 0);
    return g;
}

}  // namespace g2d::interp
