#include "interp/interpreted_rules.hpp"

#include <algorithm>
#include <cmath>

#include "g2d/placement.hpp"
#include "lower/rule_facts.hpp"

namespace g2d::interp {

using ir::PlanStep;
using rt::EdgeId;
using rt::kNoId;
using rt::NodeId;

InterpretedRules::InterpretedRules(const ProgramState& st) : st_(st) {
    std::size_t maxNodes = 0, maxEdges = 0;
    for (const auto& r : st.prog->rules) {
        lower::RuleFacts facts = lower::ruleFacts(*st.prog, r);
        rt::RuleInfo& info = facts.info;
        for (std::size_t d = 0; d < facts.weightExprs.size(); ++d) {
            if (!facts.weightExprs[d]) continue;
            EvalFrame f = st.frame(nullptr);
            try {
                info.weights[d] = rt::checkedWeight(std::get<double>(evaluate(*facts.weightExprs[d], f)));
            } catch (const rt::OpError& e) {
                throw EvalError(facts.weightExprs[d]->span, e.what());
            }
        }
        infos_.push_back(std::move(info));
        auto& rewrites = rewrites_.emplace_back();
        for (std::size_t d = 0; d < r.daughters.size(); ++d) rewrites.push_back(lower::lowerRewrite(*st.prog, r, d));
        std::size_t nacNodes = 0, nacEdges = 0;
        for (const auto& n : r.nacs) {
            nacNodes = std::max(nacNodes, n.nodes.size());
            nacEdges = std::max(nacEdges, n.edges.size());
        }
        maxNodes = std::max(maxNodes, r.nodes.size() + nacNodes);
        maxEdges = std::max(maxEdges, r.edges.size() + nacEdges);
        auto& need = neededEdgeKinds_.emplace_back(r.nodes.size(), 0);
        for (std::size_t i = 0; i < r.neededEdgeKinds.size() && i < need.size(); ++i)
            for (int k : r.neededEdgeKinds[i]) need[i] |= rt::Graph::edgeKindBit(k);
    }
    boundNodes_.assign(maxNodes, kNoId);
    boundEdges_.assign(maxEdges, kNoId);
}

// ---- matching ------------------------------------------------------------------

bool InterpretedRules::orderedOk(const rt::Graph& g, const ir::Rule& r, int node) const {
    if (!r.ordered || node >= static_cast<int>(r.nodes.size())) return true;
    const auto& si = *r.nodes[node].sketch;
    const rt::vec2 hi = g.pos(boundNodes_[node]);
    for (std::size_t j = 0; j < r.nodes.size(); ++j) {
        if (static_cast<int>(j) == node || boundNodes_[j] == kNoId) continue;
        const auto& sj = *r.nodes[j].sketch;
        const rt::vec2 hj = g.pos(boundNodes_[j]);
        // As the thesis's tool: a node drawn left of another must not match one
        // right of it (ties are allowed), and likewise for y.
        if (si.x < sj.x && hi.x > hj.x) return false;
        if (si.x > sj.x && hi.x < hj.x) return false;
        if (si.y < sj.y && hi.y > hj.y) return false;
        if (si.y > sj.y && hi.y < hj.y) return false;
    }
    return true;
}

template <class OnComplete>
bool InterpretedRules::search(const rt::Graph& g, const ir::Rule& r, const ir::NegativeCondition* nac,
                              const std::vector<PlanStep>& plan, std::size_t i, OnComplete& onComplete) {
    if (i == plan.size()) return onComplete();
    const PlanStep& s = plan[i];
    auto nodeKind = [&](int idx) {
        return idx < static_cast<int>(r.nodes.size()) ? r.nodes[idx].kind : nac->nodes[idx - nac->outerNodes].kind;
    };
    auto nodeUsed = [&](NodeId h) { return std::find(boundNodes_.begin(), boundNodes_.end(), h) != boundNodes_.end(); };

    switch (s.op) {
    case PlanStep::Op::Check: {
        EvalFrame f = st_.frame(nullptr);
        f.graph = &g;
        f.nodes = boundNodes_.data();
        f.edges = boundEdges_.data();
        const auto& cond = nac ? nac->conditions[s.condition] : r.conditions[s.condition];
        return evaluateBool(cond.expr, f) && search(g, r, nac, plan, i + 1, onComplete);
    }
    case PlanStep::Op::ScanNodes: {
        const int kind = nodeKind(s.node);
        const auto rule = static_cast<std::size_t>(&r - st_.prog->rules.data());
        auto tryHost = [&](NodeId h) {
            if (nodeUsed(h) || (!nac && !hasEdgeKinds(g, rule, s.node, h))) return false;
            boundNodes_[s.node] = h;
            const bool stop = orderedOk(g, r, s.node) && search(g, r, nac, plan, i + 1, onComplete);
            boundNodes_[s.node] = kNoId;
            return stop;
        };
        if (kind < 0) {
            for (NodeId h : g.allNodes())
                if (tryHost(h)) return true;
            return false;
        }
        const auto candidates = g.nodesOfKind(kind);
        for (std::size_t c = 0; c < candidates.size(); ++c)
            if (tryHost(candidates[c])) return true;
        return false;
    }
    case PlanStep::Op::ExtendEdge:
    case PlanStep::Op::ConnectEdge: {
        // A directed edge is looked for among the bound end's outgoing or
        // incoming edges only; an undirected one among both.
        const auto& pe = s.edge < static_cast<int>(r.edges.size()) ? r.edges[s.edge] : nac->edges[s.edge - nac->outerEdges];
        const NodeId from = boundNodes_[s.from];
        const bool outgoing = s.op == PlanStep::Op::ConnectEdge || s.fromIsSource;
        if (!g.kinds()[pe.kind].directed || outgoing)
            for (EdgeId e = g.firstOut(from); e != kNoId; e = g.nextOut(e))
                if (tryEdge(g, r, nac, plan, i, onComplete, e)) return true;
        if (!g.kinds()[pe.kind].directed || !outgoing)
            for (EdgeId e = g.firstIn(from); e != kNoId; e = g.nextIn(e))
                if (g.source(e) != g.target(e) && tryEdge(g, r, nac, plan, i, onComplete, e)) return true;
        return false;
    }
    }
    return false;
}

// One candidate edge for an ExtendEdge or ConnectEdge step.
template <class OnComplete>
bool InterpretedRules::tryEdge(const rt::Graph& g, const ir::Rule& r, const ir::NegativeCondition* nac,
                               const std::vector<PlanStep>& plan, std::size_t i, OnComplete& onComplete, EdgeId e) {
    const PlanStep& s = plan[i];
    const auto& pe = s.edge < static_cast<int>(r.edges.size()) ? r.edges[s.edge] : nac->edges[s.edge - nac->outerEdges];
    if (g.edgeKind(e) != pe.kind) return false;
    if (std::find(boundEdges_.begin(), boundEdges_.end(), e) != boundEdges_.end()) return false;
    const bool directed = g.kinds()[pe.kind].directed;
    const NodeId from = boundNodes_[s.from];
    if (s.op == PlanStep::Op::ConnectEdge) {
        const NodeId hd = boundNodes_[s.node];
        const NodeId a = g.source(e), b = g.target(e);
        const bool fits = directed ? (a == from && b == hd) : ((a == from && b == hd) || (a == hd && b == from));
        if (!fits) return false;
        boundEdges_[s.edge] = e;
        const bool stop = keptByNewEdgeGate(r, nac) && search(g, r, nac, plan, i + 1, onComplete);
        boundEdges_[s.edge] = kNoId;
        return stop;
    }
    if (directed && (s.fromIsSource ? g.source(e) != from : g.target(e) != from)) return false;
    const NodeId other = g.source(e) == from ? g.target(e) : g.source(e);
    const int farKind = s.node < static_cast<int>(r.nodes.size()) ? r.nodes[s.node].kind
                                                                   : nac->nodes[s.node - nac->outerNodes].kind;
    if (farKind >= 0 && g.nodeKind(other) != farKind) return false;
    if (std::find(boundNodes_.begin(), boundNodes_.end(), other) != boundNodes_.end()) return false;
    boundEdges_[s.edge] = e;
    boundNodes_[s.node] = other;
    const bool stop = keptByNewEdgeGate(r, nac) && orderedOk(g, r, s.node) && search(g, r, nac, plan, i + 1, onComplete);
    boundNodes_[s.node] = kNoId;
    boundEdges_[s.edge] = kNoId;
    return stop;
}

bool InterpretedRules::nacsHold(const rt::Graph& g, const ir::Rule& r) {
    auto found = [] { return true; };
    for (const auto& nac : r.nacs)
        if (search(g, r, &nac, nac.plan, 0, found)) return false;
    return true;
}

void InterpretedRules::collect(const rt::Graph& g, const ir::Rule& r, const std::vector<PlanStep>& plan,
                               rt::MatchBuffer& out) {
    auto record = [&] {
        if (nacsHold(g, r)) out.add(boundNodes_.data(), boundEdges_.data());
        return false;  // enumerate them all
    };
    search(g, r, nullptr, plan, 0, record);
}

void InterpretedRules::findMatches(std::size_t rule, const rt::Graph& g, rt::MatchBuffer& out) {
    const ir::Rule& r = st_.prog->rules[rule];
    current_ = &r;
    collect(g, r, r.plan, out);
}

void InterpretedRules::findAnchored(std::size_t rule, const rt::Graph& g, int node, rt::NodeId host,
                                    rt::MatchBuffer& out, rt::EdgeId newEdgesFrom) {
    const ir::Rule& r = st_.prog->rules[rule];
    if (!hasEdgeKinds(g, rule, node, host)) return;
    current_ = &r;
    boundNodes_[node] = host;
    newEdgesFrom_ = newEdgesFrom;
    collect(g, r, r.anchoredPlans[node], out);
    newEdgesFrom_ = kNoId;
    boundNodes_[node] = kNoId;
}

bool InterpretedRules::keptByNewEdgeGate(const ir::Rule& r, const ir::NegativeCondition* nac) const {
    if (nac || newEdgesFrom_ == kNoId) return true;
    bool fresh = false;
    for (std::size_t k = 0; k < r.edges.size(); ++k) {
        if (boundEdges_[k] == kNoId) return true;   // not all bound yet
        fresh = fresh || boundEdges_[k] >= newEdgesFrom_;
    }
    return fresh;
}

// ---- rewriting: the lowered rewrite programs, operation by operation ------------

void InterpretedRules::writeSet(std::size_t rule, std::size_t daughter, rt::Match m, rt::WriteSet& w) const {
    const lower::RewriteProgram& p = rewrites_[rule][daughter];
    for (int n : p.writtenNodes) w.nodes.push_back(m.nodes[n]);
    for (int e : p.writtenEdges) w.edges.push_back(m.edges[e]);
}

void InterpretedRules::prepare(std::size_t rule, std::size_t daughter, rt::Match m, const rt::Graph& g,
                               rt::Rng& rng, long long) {
    const ir::Rule& r = st_.prog->rules[rule];
    const lower::RewriteProgram& program = rewrites_[rule][daughter];
    current_ = &r;
    locals_.assign(static_cast<std::size_t>(r.localSlots), rt::Value{});
    EvalFrame f = st_.frame(&rng);
    f.graph = &g;
    f.nodes = m.nodes;
    f.edges = m.edges;
    f.locals = &locals_;

    if (pendingCount_ == pending_.size()) pending_.emplace_back();
    Prepared& p = pending_[pendingCount_];
    p.rule = rule;
    p.daughter = daughter;
    p.nodes.assign(m.nodes, m.nodes + r.nodes.size());
    p.edges.assign(m.edges, m.edges + r.edges.size());
    p.registers.assign(program.registers.size(), rt::Value{});
    placed_.assign(static_cast<std::size_t>(program.nodeHandles), std::nullopt);
    f.placed = &placed_;
    for (const auto& op : program.prepare) {
        std::visit(lower::Overloaded{
                       [&](const lower::EvalLocal& o) { locals_[o.slot] = evaluate(*o.value, f); },
                       [&](const lower::Place& o) { place(o, m, g); },
                       [&](const lower::Eval& o) { p.registers[o.reg] = evaluate(*o.value, f); },
                       [&](const lower::EvalPosition& o) {
                           const rt::vec2 pos = evaluateVec(*o.value, f);
                           if (!std::isfinite(pos.x) || !std::isfinite(pos.y)) throw EvalError(o.value->span, o.message);
                           p.registers[o.reg] = pos;
                       },
                       [&](const lower::TakePlaced& o) { p.registers[o.reg] = *placed_[o.daughterNode]; },
                   },
                   op);
    }
    ++pendingCount_;
}

void InterpretedRules::place(const lower::Place& o, rt::Match m, const rt::Graph& g) {
    std::vector<rt::vec2> mother, host, refDaughter, refHost;
    for (std::size_t i = 0; i < o.motherSketch.size(); ++i) {
        mother.push_back({o.motherSketch[i].x, o.motherSketch[i].y});
        host.push_back(g.pos(m.nodes[i]));
    }
    for (const auto& [sketch, node] : o.refs) {
        refDaughter.push_back({sketch.x, sketch.y});
        refHost.push_back(host[static_cast<std::size_t>(node)]);
    }
    if (refDaughter.empty()) {
        refDaughter = mother;
        refHost = host;
    }
    const rt::PlacementFrame frame = rt::placementFrame(mother, host, o.directed, refDaughter, refHost);
    for (const auto& t : o.targets) {
        const rt::vec2 pos = frame.place({t.sketch.x, t.sketch.y});
        if (!std::isfinite(pos.x) || !std::isfinite(pos.y)) throw EvalError(t.span, t.message);
        placed_[t.daughterNode] = pos;
    }
}

void InterpretedRules::commit(rt::Graph& g, long long step) {
    for (std::size_t k = 0; k < pendingCount_; ++k) {
        Prepared& p = pending_[k];
        const lower::RewriteProgram& program = rewrites_[p.rule][p.daughter];
        auto value = [&](const lower::Operand& v) { return v.reg >= 0 ? std::move(p.registers[v.reg]) : fromLiteral(v.literal->value); };
        auto& nodes = hostOf_;
        auto& edges = edgeOf_;
        nodes.assign(static_cast<std::size_t>(program.nodeHandles), kNoId);
        edges.assign(static_cast<std::size_t>(program.edgeHandles), kNoId);
        for (const auto& op : program.commit) {
            std::visit(lower::Overloaded{
                           [&](const lower::DeleteEdge& o) { g.removeEdge(p.edges[o.matchEdge]); },
                           [&](const lower::BindNode& o) { nodes[o.handle] = p.nodes[o.matchNode]; },
                           [&](const lower::CreateNode& o) {
                               nodes[o.handle] = g.addNode(o.kind, std::get<rt::vec2>(p.registers[o.posReg]), step);
                               for (const auto& w : o.attrs) g.initNodeAttr(nodes[o.handle], w.attr, value(w.value));
                           },
                           [&](const lower::Rewire& o) { g.reconnectEdge(p.edges[o.matchEdge], nodes[o.src], nodes[o.dst]); },
                           [&](const lower::DeleteNode& o) { g.removeNode(p.nodes[o.matchNode]); },
                           [&](const lower::SetPos& o) { g.setPos(nodes[o.handle], std::get<rt::vec2>(p.registers[o.reg])); },
                           [&](const lower::SetNodeAttr& o) { g.initNodeAttr(nodes[o.handle], o.write.attr, value(o.write.value)); },
                           [&](const lower::TouchNodeValues& o) { g.touchNodeValues(nodes[o.handle]); },
                           [&](const lower::SetNodeStyle& o) {
                               g.setNodeStyle(nodes[o.handle], static_cast<rt::StyleProp>(o.style->propId), value(o.value));
                           },
                           [&](const lower::BindEdge& o) { edges[o.handle] = p.edges[o.matchEdge]; },
                           [&](const lower::SetEdgeAttr& o) { g.initEdgeAttr(edges[o.handle], o.write.attr, value(o.write.value)); },
                           [&](const lower::TouchEdge& o) { g.touchEdgeItself(edges[o.handle]); },
                           [&](const lower::CreateEdge& o) {
                               edges[o.handle] = g.addEdge(o.kind, nodes[o.src], nodes[o.dst], step);
                               for (const auto& w : o.attrs) g.initEdgeAttr(edges[o.handle], w.attr, value(w.value));
                           },
                           [&](const lower::SetEdgeStyle& o) {
                               g.setEdgeStyle(edges[o.handle], static_cast<rt::StyleProp>(o.style->propId), value(o.value));
                           },
                       },
                       op);
        }
    }
    pendingCount_ = 0;
}

}  // namespace g2d::interp
