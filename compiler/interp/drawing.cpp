#include "interp/drawing.hpp"

namespace g2d::interp {

namespace {

// Enums print by name, so writers never see enum values.
rt::Value printable(rt::Value v, const ir::Program& prog) {
    if (std::holds_alternative<rt::EnumVal>(v)) return display(v, prog);
    return v;
}

void resolve(rt::DrawItem& item, const ir::Kind& kind, rt::StyleList own, const rt::Graph& g, EvalFrame& f,
             const ir::Program& prog) {
    for (const auto& p : kind.style) item.props.push_back({p.name, printable(evaluate(p.value, f), prog)});
    for (const auto& o : own) {
        const std::string& name = g.stylePropName(o.prop);
        bool replaced = false;
        for (auto& p : item.props)
            if (p.prop == name) { p.value = printable(o.value, prog); replaced = true; }
        if (!replaced) item.props.push_back({name, printable(o.value, prog)});
    }
}

}  // namespace

std::vector<rt::DrawItem> drawItems(const rt::Graph& g, const ProgramState& st) {
    const ir::Program& prog = *st.prog;
    std::vector<rt::DrawItem> items;
    EvalFrame f = st.frame(nullptr);
    f.graph = &g;
    for (rt::EdgeId e = 0; e < g.edgeCapacity(); ++e) {
        if (!g.edgeAlive(e)) continue;
        rt::DrawItem item;
        item.cls = rt::ElemClass::Edge;
        item.id = e;
        item.a = g.pos(g.source(e));
        item.b = g.pos(g.target(e));
        f.selfClass = ir::ElemClass::Edge;
        f.self = e;
        resolve(item, prog.kinds[g.edgeKind(e)], g.edgeStyle(e), g, f, prog);
        items.push_back(std::move(item));
    }
    for (rt::NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        rt::DrawItem item;
        item.id = n;
        item.a = g.pos(n);
        f.selfClass = ir::ElemClass::Node;
        f.self = n;
        resolve(item, prog.kinds[g.nodeKind(n)], g.nodeStyle(n), g, f, prog);
        items.push_back(std::move(item));
    }
    return items;
}

rt::JsonSchema jsonSchema(const ir::Program& prog) {
    rt::JsonSchema s;
    for (const auto& k : prog.kinds) {
        s.kindNames.push_back(k.name);
        std::vector<std::string> attrs;
        for (const auto& a : k.attrs) attrs.push_back(a.name);
        s.attrNames.push_back(std::move(attrs));
    }
    for (const auto& e : prog.enums) s.enumValueNames.push_back(e.values);
    return s;
}

}  // namespace g2d::interp
