#include "interp/drawing.hpp"

#include "g2d/draw_items.hpp"

namespace g2d::interp {

void drawItem(const rt::Graph& g, const ProgramState& st, const std::vector<std::vector<std::string>>& enumNames,
              rt::ElemClass cls, std::uint32_t id, rt::DrawItem& out) {
    const ir::Program& prog = st.program();
    EvalFrame f = st.frame(nullptr);
    f.graph = &g;
    rt::drawItem(g, cls, id, enumNames, [&](rt::DrawItem& item, int kind) {
        f.selfClass = item.cls;
        f.self = item.id;
        for (const auto& p : prog.kinds[kind].style) item.props.push_back({p.name, evaluate(p.value, f)});
    }, out);
}

std::vector<rt::DrawItem> drawItems(const rt::Graph& g, const ProgramState& st) {
    std::vector<std::vector<std::string>> enumNames;
    for (const auto& e : st.program().enums) enumNames.push_back(e.values);
    return rt::drawItems(g, [&](rt::ElemClass cls, std::uint32_t id, rt::DrawItem& out) {
        drawItem(g, st, enumNames, cls, id, out);
    });
}

rt::JsonSchema jsonSchema(const ir::Program& prog) {
    rt::JsonSchema s;
    s.space3d = prog.space3d;
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
