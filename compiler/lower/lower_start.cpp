#include "lower/start_program.hpp"

namespace g2d::lower {

namespace {

// The axiom's values are evaluated in the order it is written (per node its
// position, attributes and styles; then per edge, then per face, its
// attributes and styles); then its nodes are created, with their styles,
// then its edges, then its faces.
RewriteProgram lowerAxiom(const ir::Axiom& ax, const ir::Program& prog) {
    RewriteProgram p;
    p.nodeHandles = static_cast<int>(ax.nodes.size());
    p.edgeHandles = static_cast<int>(ax.edges.size());
    p.faceHandles = static_cast<int>(ax.faces.size());
    auto operand = [&](const ir::Expr& value) {
        if (value.op == ir::ExprOp::Literal) return Operand{-1, &value, value.type};
        p.registers.push_back(value.type);
        const int reg = static_cast<int>(p.registers.size() - 1);
        p.prepare.push_back(Eval{reg, &value});
        return Operand{reg, nullptr, value.type};
    };
    std::vector<CommitOp> nodes, edges, faces;
    for (std::size_t i = 0; i < ax.nodes.size(); ++i) {
        const auto& n = ax.nodes[i];
        const int h = static_cast<int>(i);
        int posReg = -1;
        if (n.position) {
            p.registers.push_back(ir::positionType(prog));
            posReg = static_cast<int>(p.registers.size() - 1);
            p.prepare.push_back(EvalPosition{posReg, &*n.position, "position of `" + n.name + "` is not finite"});
        }
        CreateNode create{h, n.kind, posReg, {}};
        for (const auto& a : n.assigns) create.attrs.push_back(AttrWrite{a.attr, operand(a.value)});
        nodes.push_back(std::move(create));
        if (n.radius) nodes.push_back(SetRadius{h, operand(*n.radius)});
        for (const auto& s : n.styles) nodes.push_back(SetNodeStyle{h, &s, operand(s.value)});
    }
    for (std::size_t i = 0; i < ax.edges.size(); ++i) {
        const auto& e = ax.edges[i];
        const int h = static_cast<int>(i);
        CreateEdge create{h, e.kind, e.src, e.dst, {}};
        for (const auto& a : e.assigns) create.attrs.push_back(AttrWrite{a.attr, operand(a.value)});
        edges.push_back(std::move(create));
        for (const auto& s : e.styles) edges.push_back(SetEdgeStyle{h, &s, operand(s.value)});
    }
    for (std::size_t i = 0; i < ax.faces.size(); ++i) {
        const auto& f = ax.faces[i];
        const int h = static_cast<int>(i);
        CreateFace create{h, f.kind, f.corners, {}, prog.kinds[f.kind].oriented};
        for (const auto& a : f.assigns) create.attrs.push_back(AttrWrite{a.attr, operand(a.value)});
        faces.push_back(std::move(create));
        for (const auto& s : f.styles) faces.push_back(SetFaceStyle{h, &s, operand(s.value), false});
    }
    p.commit = std::move(nodes);
    p.commit.insert(p.commit.end(), std::make_move_iterator(edges.begin()), std::make_move_iterator(edges.end()));
    p.commit.insert(p.commit.end(), std::make_move_iterator(faces.begin()), std::make_move_iterator(faces.end()));
    return p;
}

}  // namespace

StartProgram lowerStart(const ir::Program& prog) {
    StartProgram s;
    for (std::size_t c = 0; c < prog.consts.size(); ++c) s.init.push_back(InitConst{static_cast<int>(c), &prog.consts[c]});
    for (std::size_t k = 0; k < prog.kinds.size(); ++k)
        for (std::size_t a = 0; a < prog.kinds[k].attrs.size(); ++a)
            s.init.push_back(InitDefault{static_cast<int>(k), static_cast<int>(a), &prog.kinds[k].attrs[a].defaultValue});
    s.axiom = lowerAxiom(prog.axiom, prog);
    return s;
}

}  // namespace g2d::lower
