#include "interp/program_state.hpp"

namespace g2d::interp {

EvalFrame ProgramState::frame(rt::Rng* rng) const {
    EvalFrame f;
    f.prog = prog;
    f.params = &params;
    f.consts = &consts;
    f.rng = rng;
    return f;
}

ProgramState initState(const ir::Program& prog, std::vector<rt::Value> params, rt::Rng& rng) {
    ProgramState st;
    st.prog = &prog;
    st.params = std::move(params);
    for (const auto& c : prog.consts) {
        EvalFrame f = st.frame(&rng);
        st.consts.push_back(c.folded ? fromLiteral(*c.folded) : evaluate(c.value, f));
    }
    for (const auto& k : prog.kinds) {
        std::vector<rt::Value> defaults;
        for (const auto& a : k.attrs) {
            EvalFrame f = st.frame(&rng);
            defaults.push_back(evaluate(a.defaultValue, f));
        }
        st.kindDefaults.push_back(std::move(defaults));
    }
    return st;
}

std::vector<rt::KindInfo> kindInfos(const ir::Program& prog) {
    std::vector<rt::KindInfo> out;
    for (const auto& k : prog.kinds) out.push_back(rt::KindInfo{k.cls, k.directed});
    return out;
}

rt::Graph buildAxiom(const ProgramState& st, rt::Rng& rng) {
    const ir::Program& prog = *st.prog;
    rt::Graph g(kindInfos(prog), prog.styleProps);
    for (std::size_t k = 0; k < st.kindDefaults.size(); ++k) g.setKindDefaults(static_cast<int>(k), st.kindDefaults[k]);
    std::vector<rt::NodeId> ids;
    for (const auto& n : prog.axiom.nodes) {
        EvalFrame f = st.frame(&rng);
        rt::vec2 pos{0, 0};
        if (n.position) pos = evaluateVec(*n.position, f);
        std::vector<rt::Value> attrs = st.kindDefaults[n.kind];
        for (const auto& a : n.assigns) attrs[a.attr] = evaluate(a.value, f);
        const rt::NodeId id = g.addNode(n.kind, pos, 0, std::move(attrs));
        for (const auto& s : n.styles) g.setNodeStyle(id, static_cast<rt::StyleProp>(s.propId), evaluate(s.value, f));
        ids.push_back(id);
    }
    for (const auto& e : prog.axiom.edges) {
        EvalFrame f = st.frame(&rng);
        std::vector<rt::Value> attrs = st.kindDefaults[e.kind];
        for (const auto& a : e.assigns) attrs[a.attr] = evaluate(a.value, f);
        const rt::EdgeId id = g.addEdge(e.kind, ids[e.src], ids[e.dst], 0, std::move(attrs));
        for (const auto& s : e.styles) g.setEdgeStyle(id, static_cast<rt::StyleProp>(s.propId), evaluate(s.value, f));
    }
    return g;
}

}  // namespace g2d::interp
