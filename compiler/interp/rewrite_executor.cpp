#include "interp/rewrite_executor.hpp"

#include <cmath>

#include "g2d/placement.hpp"

namespace g2d::interp {

void RewriteExecutor::prepare(const lower::RewriteProgram& p, rt::Match m, const rt::Graph& g, EvalFrame& f,
                              std::vector<rt::Value>& registers) {
    placed_.assign(static_cast<std::size_t>(p.nodeHandles), std::nullopt);
    f.placed = &placed_;
    for (const auto& op : p.prepare) {
        std::visit(lower::Overloaded{
                       [&](const lower::EvalLocal& o) { (*f.locals)[o.slot] = evaluate(*o.value, f); },
                       [&](const lower::Place& o) { place(o, m, g); },
                       [&](const lower::Eval& o) { registers[o.reg] = evaluate(*o.value, f); },
                       [&](const lower::EvalPosition& o) {
                           const rt::vec2 pos = evaluateVec(*o.value, f);
                           if (!std::isfinite(pos.x) || !std::isfinite(pos.y)) throw EvalError(o.value->span, o.message);
                           registers[o.reg] = pos;
                       },
                       [&](const lower::TakePlaced& o) { registers[o.reg] = *placed_[o.daughterNode]; },
                   },
                   op);
    }
}

void RewriteExecutor::place(const lower::Place& o, rt::Match m, const rt::Graph& g) {
    std::vector<rt::vec2> mother, host, refDaughter, refHost;
    for (std::size_t i = 0; i < o.motherSketch.size(); ++i) {
        mother.push_back({o.motherSketch[i].x, o.motherSketch[i].y});
        host.push_back(g.pos(m.nodes[i]));
    }
    for (const auto& [sketch, node] : o.refs) {
        refDaughter.push_back({sketch.x, sketch.y});
        refHost.push_back(host[static_cast<std::size_t>(node)]);
    }
    const rt::PlacementFrame frame = rt::placementFrame(mother, host, o.directed, refDaughter, refHost);
    for (const auto& t : o.targets) {
        const rt::vec2 pos = frame.place({t.sketch.x, t.sketch.y});
        if (!std::isfinite(pos.x) || !std::isfinite(pos.y)) throw EvalError(t.span, t.message);
        placed_[t.daughterNode] = pos;
    }
}

void RewriteExecutor::commit(const lower::RewriteProgram& p, rt::Match m, std::vector<rt::Value>& registers, rt::Graph& g,
                             long long step) {
    auto value = [&](const lower::Operand& v) { return v.reg >= 0 ? std::move(registers[v.reg]) : fromLiteral(v.literal->value); };
    auto position = [&](int reg) { return reg >= 0 ? std::get<rt::vec2>(registers[reg]) : rt::vec2{0, 0}; };
    auto& nodes = hostOf_;
    auto& edges = edgeOf_;
    auto& faces = faceOf_;
    nodes.assign(static_cast<std::size_t>(p.nodeHandles), rt::kNoId);
    edges.assign(static_cast<std::size_t>(p.edgeHandles), rt::kNoId);
    faces.assign(static_cast<std::size_t>(p.faceHandles), rt::kNoId);
    for (const auto& op : p.commit) {
        std::visit(lower::Overloaded{
                       [&](const lower::DeleteFace& o) { g.removeFace(m.faces[o.matchFace]); },
                       [&](const lower::DeleteEdge& o) { g.removeEdge(m.edges[o.matchEdge]); },
                       [&](const lower::BindNode& o) { nodes[o.handle] = m.nodes[o.matchNode]; },
                       [&](const lower::CreateNode& o) {
                           nodes[o.handle] = g.addNode(o.kind, position(o.posReg), step);
                           for (const auto& w : o.attrs) g.initNodeAttr(nodes[o.handle], w.attr, value(w.value));
                       },
                       [&](const lower::Rewire& o) { g.reconnectEdge(m.edges[o.matchEdge], nodes[o.src], nodes[o.dst]); },
                       [&](const lower::DeleteNode& o) { g.removeNode(m.nodes[o.matchNode]); },
                       [&](const lower::SetPos& o) { g.setPos(nodes[o.handle], std::get<rt::vec2>(registers[o.reg])); },
                       [&](const lower::SetNodeAttr& o) { g.initNodeAttr(nodes[o.handle], o.write.attr, value(o.write.value)); },
                       [&](const lower::TouchNodeValues& o) { g.touchNodeValues(nodes[o.handle]); },
                       [&](const lower::SetNodeStyle& o) {
                           g.setNodeStyle(nodes[o.handle], static_cast<rt::StyleProp>(o.style->propId), value(o.value));
                       },
                       [&](const lower::BindEdge& o) { edges[o.handle] = m.edges[o.matchEdge]; },
                       [&](const lower::SetEdgeAttr& o) { g.initEdgeAttr(edges[o.handle], o.write.attr, value(o.write.value)); },
                       [&](const lower::TouchEdge& o) { g.touchEdgeItself(edges[o.handle]); },
                       [&](const lower::CreateEdge& o) {
                           edges[o.handle] = g.addEdge(o.kind, nodes[o.src], nodes[o.dst], step);
                           for (const auto& w : o.attrs) g.initEdgeAttr(edges[o.handle], w.attr, value(w.value));
                       },
                       [&](const lower::SetEdgeStyle& o) {
                           g.setEdgeStyle(edges[o.handle], static_cast<rt::StyleProp>(o.style->propId), value(o.value));
                       },
                       [&](const lower::BindFace& o) { faces[o.handle] = m.faces[o.matchFace]; },
                       [&](const lower::SetFaceAttr& o) {
                           if (g.faceAlive(faces[o.handle])) g.initFaceAttr(faces[o.handle], o.write.attr, value(o.write.value));
                       },
                       [&](const lower::TouchFace& o) {
                           if (g.faceAlive(faces[o.handle])) g.touchFaceValues(faces[o.handle]);
                       },
                       [&](const lower::CreateFace& o) {
                           corners_.clear();
                           for (int c : o.corners) corners_.push_back(nodes[c]);
                           faces[o.handle] = g.addFace(o.kind, corners_, step);
                           for (const auto& w : o.attrs) g.initFaceAttr(faces[o.handle], w.attr, value(w.value));
                       },
                       [&](const lower::SetFaceStyle& o) {
                           if (g.faceAlive(faces[o.handle])) g.setFaceStyle(faces[o.handle], static_cast<rt::StyleProp>(o.style->propId), value(o.value));
                       },
                   },
                   op);
    }
}

}  // namespace g2d::interp
