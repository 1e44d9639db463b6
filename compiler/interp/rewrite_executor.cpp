#include "interp/rewrite_executor.hpp"

#include <algorithm>
#include <cmath>

#include "g2d/daughter_faces.hpp"
#include "g2d/face_split.hpp"
#include "g2d/placement.hpp"

namespace g2d::interp {

void RewriteExecutor::prepare(const lower::RewriteProgram& p, rt::Match m, const rt::Graph& g, EvalFrame& f,
                              std::vector<rt::Value>& registers, std::vector<LoopValues>& loops) {
    placed_.assign(static_cast<std::size_t>(p.nodeHandles), std::nullopt);
    f.placed = &placed_;
    loops.resize(p.loops.size());
    for (const auto& op : p.prepare) {
        std::visit(lower::Overloaded{
                       [&](const lower::EvalLocal& o) { (*f.locals)[o.slot] = evaluate(*o.value, f); },
                       [&](const lower::Place& o) { place(o, m, g); },
                       [&](const lower::Eval& o) { registers[o.reg] = evaluate(*o.value, f); },
                       [&](const lower::EvalPosition& o) { registers[o.reg] = evaluatePosition(o, f); },
                       [&](const lower::TakePlaced& o) { registers[o.reg] = *placed_[o.daughterNode]; },
                       [&](const lower::PrepareLoop& o) { prepareLoop(p.loops[o.loop], m, g, f, loops[o.loop]); },
                   },
                   op);
    }
}

void RewriteExecutor::prepareLoop(const lower::LoopProgram& l, rt::Match m, const rt::Graph& g, EvalFrame& f, LoopValues& out) {
    const rt::FaceId face = m.faces[l.matchFace];
    out.corners.clear();
    rt::CornerId c = g.firstCorner(face);
    for (int i = 0; i < g.cornerCount(face); ++i, c = g.nextCorner(c)) out.corners.push_back(g.cornerNode(c));
    const std::size_t turns = out.corners.size(), regs = l.registers.size();
    out.registers.assign(turns * regs, rt::Value{});
    // The turn's corners read as match nodes firstVar (u) and firstVar + 1 (v).
    loopFrame_.assign(m.nodes, m.nodes + l.firstVar);
    loopFrame_.resize(static_cast<std::size_t>(l.firstVar) + 2, rt::kNoId);
    const rt::NodeId* matchNodes = f.nodes;
    f.nodes = loopFrame_.data();
    for (std::size_t t = 0; t < turns; ++t) {
        loopFrame_[static_cast<std::size_t>(l.firstVar)] = out.corners[t];
        loopFrame_[static_cast<std::size_t>(l.firstVar) + 1] = out.corners[(t + 1) % turns];
        rt::Value* r = out.registers.data() + t * regs;
        for (const auto& op : l.prepare) {
            if (const auto* e = std::get_if<lower::Eval>(&op)) {
                r[e->reg] = evaluate(*e->value, f);
            } else {
                r[std::get<lower::EvalPosition>(op).reg] = evaluatePosition(std::get<lower::EvalPosition>(op), f);
            }
        }
    }
    f.nodes = matchNodes;
}

rt::Value RewriteExecutor::evaluatePosition(const lower::EvalPosition& o, EvalFrame& f) {
    rt::Value pos = evaluate(*o.value, f);
    if (!rt::isFinitePosition(pos)) throw EvalError(o.value->span, o.message);
    return pos;
}

void RewriteExecutor::place(const lower::Place& o, rt::Match m, const rt::Graph& g) {
    std::vector<rt::vec2> mother, host, refDaughter, refHost;
    std::vector<double> refZ;
    for (std::size_t i = 0; i < o.motherSketch.size(); ++i) {
        mother.push_back({o.motherSketch[i].x, o.motherSketch[i].y});
        host.push_back(g.pos(m.nodes[o.members[i]]));
    }
    for (const auto& [sketch, node] : o.refs) {
        refDaughter.push_back({sketch.x, sketch.y});
        refHost.push_back(g.pos(m.nodes[node]));
        if (o.space3d) refZ.push_back(g.z(m.nodes[node]));   // 2D grammars have no z
    }
    const rt::PlacementFrame frame = rt::placementFrame(mother, host, o.directed, refDaughter, refHost, refZ);
    for (const auto& t : o.targets) {
        const rt::vec2 pos = frame.place({t.sketch.x, t.sketch.y});
        if (!std::isfinite(pos.x) || !std::isfinite(pos.y)) throw EvalError(t.span, t.message);
        placed_[t.daughterNode] = o.space3d ? rt::Value{frame.place3({t.sketch.x, t.sketch.y})} : rt::Value{pos};
    }
}

void RewriteExecutor::commit(const lower::RewriteProgram& p, rt::Match m, std::vector<rt::Value>& registers,
                             std::vector<LoopValues>& loops, rt::Graph& g, long long step) {
    hostOf_.assign(static_cast<std::size_t>(p.nodeHandles), rt::kNoId);
    edgeOf_.assign(static_cast<std::size_t>(p.edgeHandles), rt::kNoId);
    faceOf_.assign(static_cast<std::size_t>(p.faceHandles), rt::kNoId);
    apply(p.commit, m, registers, g, step, p, loops);
}

void RewriteExecutor::commitLoop(const lower::LoopProgram& l, LoopValues& values, rt::Graph& g, long long step,
                                 const lower::RewriteProgram& p, std::vector<LoopValues>& loops) {
    const std::size_t turns = values.corners.size(), regs = l.registers.size(), L = static_cast<std::size_t>(l.localNodes);
    const std::size_t H = static_cast<std::size_t>(l.outerNodes);
    const std::vector<rt::NodeId> outer(hostOf_.begin(), hostOf_.begin() + static_cast<long>(H));
    turnNodes_.assign(turns * L, rt::kNoId);
    std::vector<rt::Value> turnRegisters;
    // The handles of turn t (lower::LoopProgram's numbering).
    auto frame = [&](std::size_t t) {
        hostOf_ = outer;
        hostOf_.resize(static_cast<std::size_t>(l.nodeHandles()), rt::kNoId);
        hostOf_[H] = values.corners[t];
        hostOf_[H + 1] = values.corners[(t + 1) % turns];
        for (std::size_t i = 0; i < L; ++i) {
            hostOf_[H + 2 + i] = turnNodes_[t * L + i];
            hostOf_[H + 2 + L + i] = turnNodes_[((t + turns - 1) % turns) * L + i];
            hostOf_[H + 2 + 2 * L + i] = turnNodes_[((t + 1) % turns) * L + i];
        }
        edgeOf_.assign(static_cast<std::size_t>(l.edgeHandles), rt::kNoId);
        faceOf_.assign(static_cast<std::size_t>(l.faceHandles), rt::kNoId);
        turnRegisters.assign(std::make_move_iterator(values.registers.begin() + static_cast<long>(t * regs)),
                             std::make_move_iterator(values.registers.begin() + static_cast<long>((t + 1) * regs)));
    };
    for (std::size_t t = 0; t < turns; ++t) {
        frame(t);
        // Styles and attributes are used once each: create moves them, link gets the rest.
        apply(l.create, rt::Match{}, turnRegisters, g, step, p, loops);
        for (std::size_t i = 0; i < L; ++i) turnNodes_[t * L + i] = hostOf_[H + 2 + i];
        std::move(turnRegisters.begin(), turnRegisters.end(), values.registers.begin() + static_cast<long>(t * regs));
    }
    for (std::size_t t = 0; t < turns; ++t) {
        frame(t);
        apply(l.link, rt::Match{}, turnRegisters, g, step, p, loops);
    }
    hostOf_ = outer;
    values.made = turnNodes_;
}

// Node `turnNode` of every turn (lower::CreateRingFace), in turn order or reversed.
void RewriteExecutor::ringCorners(const lower::CreateRingFace& o, const lower::LoopProgram& l, const LoopValues& values) {
    const std::size_t turns = values.corners.size(), L = static_cast<std::size_t>(l.localNodes);
    corners_.clear();
    for (std::size_t k = 0; k < turns; ++k) {
        const std::size_t t = o.reversed ? turns - 1 - k : k;
        corners_.push_back(o.turnNode == 0   ? values.corners[t]
                           : o.turnNode == 1 ? values.corners[(t + 1) % turns]
                                             : values.made[t * L + static_cast<std::size_t>(o.turnNode - 2)]);
    }
}

void RewriteExecutor::apply(const std::vector<lower::CommitOp>& ops, rt::Match m, std::vector<rt::Value>& registers, rt::Graph& g,
                            long long step, const lower::RewriteProgram& p, std::vector<LoopValues>& loops) {
    auto value = [&](const lower::Operand& v) { return v.reg >= 0 ? std::move(registers[v.reg]) : fromLiteral(v.literal->value); };
    // A position register holds a vec2, or a vec3 in a 3D grammar.
    auto addNode = [&](int kind, int reg) {
        if (reg < 0) return g.addNode(kind, rt::vec2{0, 0}, step);
        if (const auto* p3 = std::get_if<rt::vec3>(&registers[reg])) return g.addNode(kind, *p3, step);
        return g.addNode(kind, std::get<rt::vec2>(registers[reg]), step);
    };
    auto& nodes = hostOf_;
    auto& edges = edgeOf_;
    auto& faces = faceOf_;
    for (const auto& op : ops) {
        std::visit(lower::Overloaded{
                       [&](const lower::DeleteFace& o) { g.removeFace(m.faces[o.matchFace]); },
                       [&](const lower::DeleteEdge& o) { g.removeEdge(m.edges[o.matchEdge]); },
                       [&](const lower::BindNode& o) { nodes[o.handle] = m.nodes[o.matchNode]; },
                       [&](const lower::CreateNode& o) {
                           nodes[o.handle] = addNode(o.kind, o.posReg);
                           for (const auto& w : o.attrs) g.initNodeAttr(nodes[o.handle], w.attr, value(w.value));
                       },
                       [&](const lower::Rewire& o) { g.reconnectEdge(m.edges[o.matchEdge], nodes[o.src], nodes[o.dst]); },
                       [&](const lower::DeleteNode& o) { g.removeNode(m.nodes[o.matchNode]); },
                       [&](const lower::SetPos& o) {
                           if (const auto* p3 = std::get_if<rt::vec3>(&registers[o.reg])) g.setPos(nodes[o.handle], *p3);
                           else g.setPos(nodes[o.handle], std::get<rt::vec2>(registers[o.reg]));
                       },
                       [&](const lower::SetRadius& o) { g.setRadius(nodes[o.handle], std::get<double>(value(o.value))); },
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
                           if (!o.ifAlive || g.faceAlive(faces[o.handle])) g.initFaceAttr(faces[o.handle], o.write.attr, value(o.write.value));
                       },
                       [&](const lower::TouchFace& o) {
                           if (!o.ifAlive || g.faceAlive(faces[o.handle])) g.touchFaceValues(faces[o.handle]);
                       },
                       [&](const lower::CreateFace& o) {
                           corners_.clear();
                           for (int c : o.corners) corners_.push_back(nodes[c]);
                           faces[o.handle] = rt::addDaughterFace(g, o.kind, corners_, step, o.orient);
                           for (const auto& w : o.attrs) g.initFaceAttr(faces[o.handle], w.attr, value(w.value));
                       },
                       [&](const lower::SetFaceStyle& o) {
                           if (!o.ifAlive || g.faceAlive(faces[o.handle])) g.setFaceStyle(faces[o.handle], static_cast<rt::StyleProp>(o.style->propId), value(o.value));
                       },
                       [&](const lower::InsertBetween& o) { rt::insertDaughterCorner(g, nodes[o.first], nodes[o.second], nodes[o.node]); },
                       [&](const lower::CommitLoop& o) { commitLoop(p.loops[o.loop], loops[o.loop], g, step, p, loops); },
                       [&](const lower::CreateRingFace& o) {
                           ringCorners(o, p.loops[static_cast<std::size_t>(o.loop)], loops[static_cast<std::size_t>(o.loop)]);
                           faces[o.handle] = rt::addDaughterFace(g, o.kind, corners_, step, o.orient);
                           for (const auto& w : o.attrs) g.initFaceAttr(faces[o.handle], w.attr, value(w.value));
                       },
                       [&](const lower::SplitFace& o) { split(p.splits[o.split], faces[o.face], registers, g, step, p, loops); },
                   },
                   op);
    }
}

// The chosen corners, then the cut (rt::splitFace), whose makers run the
// split's operations; each run reads a copy of the registers (they are used
// once per edge).
void RewriteExecutor::split(const lower::SplitProgram& s, rt::FaceId face, const std::vector<rt::Value>& registers, rt::Graph& g,
                            long long step, const lower::RewriteProgram& p, std::vector<LoopValues>& loops) {
    const LoopValues& turns = loops[static_cast<std::size_t>(s.loop)];
    const std::size_t regs = p.loops[static_cast<std::size_t>(s.loop)].registers.size();
    std::vector<rt::NodeId> chosen;
    for (std::size_t t = 0; t < turns.corners.size(); ++t)
        if (s.chosenReg < 0 || std::get<bool>(turns.registers[t * regs + static_cast<std::size_t>(s.chosenReg)])) chosen.push_back(turns.corners[t]);
    hostOf_.resize(std::max(hostOf_.size(), static_cast<std::size_t>(p.nodeHandles)), rt::kNoId);
    edgeOf_.resize(std::max(edgeOf_.size(), static_cast<std::size_t>(p.edgeHandles)), rt::kNoId);
    std::vector<rt::Value> scratch;
    rt::SplitMakers make;
    if (!s.makeCentre.empty())
        make.centre = [&] {
            scratch = registers;
            apply(s.makeCentre, rt::Match{}, scratch, g, step, p, loops);
            return hostOf_[static_cast<std::size_t>(s.to)];
        };
    make.edge = [&](rt::NodeId from, rt::NodeId to) {
        hostOf_[static_cast<std::size_t>(s.from)] = from;
        hostOf_[static_cast<std::size_t>(s.to)] = to;
        scratch = registers;
        apply(s.makeEdge, rt::Match{}, scratch, g, step, p, loops);
        return edgeOf_[static_cast<std::size_t>(s.edgeHandle)];
    };
    make.copyFace = [&](rt::FaceId from, rt::FaceId to) { g.copyFaceAttrs(from, to); };
    rt::splitFace(g, face, chosen, make, step);
}

}  // namespace g2d::interp
