#include "interp/interpreted_rules.hpp"

#include <algorithm>
#include <cmath>

#include "g2d/placement.hpp"

// The IR's edge-list bits are the runtime's (ir::Rule::readDirections is
// handed over as is, and generated code writes the same numbers).
static_assert(g2d::ir::kReadsOutEdges == g2d::rt::RepairArea::kOut && g2d::ir::kReadsInEdges == g2d::rt::RepairArea::kIn);

namespace g2d::interp {

using ir::PlanStep;
using rt::EdgeId;
using rt::kNoId;
using rt::NodeId;

namespace {

rt::Incidence incidence(ir::IncidenceRead r) {
    switch (r) {
    case ir::IncidenceRead::None: return rt::Incidence::None;
    case ir::IncidenceRead::PatternEdges: return rt::Incidence::PatternEdges;
    case ir::IncidenceRead::AllEdges: return rt::Incidence::AllEdges;
    }
    return rt::Incidence::AllEdges;
}

}  // namespace

InterpretedRules::InterpretedRules(const ProgramState& st) : st_(st) {
    std::size_t maxNodes = 0, maxEdges = 0;
    for (const auto& r : st.prog->rules) {
        rt::RuleInfo info;
        info.name = r.name;
        info.priority = r.priority;
        info.pick = r.pick == ir::Pick::Oldest ? rt::Pick::Oldest : rt::Pick::Random;
        auto prio = st.prog->priorities.find(r.priority);
        info.parallel = r.parallel || (prio != st.prog->priorities.end() && prio->second.parallel);
        for (const auto& d : r.daughters) {
            double w = 1;
            if (d.weight) {
                w = *d.weight;
            } else if (d.weightExpr) {
                EvalFrame f = st.frame(nullptr);
                rt::Value v = evaluate(*d.weightExpr, f);
                w = std::get<double>(v);
                if (!(w > 0) || !std::isfinite(w))
                    throw EvalError(d.weightExpr->span, "a weight must be positive, but this is " + rt::formatNumber(w));
            }
            info.weights.push_back(w);
        }
        info.radius = r.repairRadius;
        for (ir::IncidenceRead read : r.readsIncidence) info.readsIncidence.push_back(incidence(read));
        info.readDirections = r.readDirections;
        for (bool nothing : r.newHostAddsNothing) info.newHostAddsNothing.push_back(nothing ? 1 : 0);
        for (const auto& n : r.nodes) info.nodeKinds.push_back(n.kind);
        info.edgeCount = static_cast<int>(r.edges.size());
        info.kindsKnown = true;
        info.readKinds = r.readKinds;
        info.readsDegrees = r.readsDegrees;
        info.readValues = r.readValues;
        for (const auto& d : r.daughters) {
            info.changedKinds.push_back(d.changedKinds);
            info.changedValues.push_back(d.changedValues);
            info.deletesNodes.push_back(d.deletedNodes.empty() ? 0 : 1);
        }
        infos_.push_back(std::move(info));
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

// ---- rewriting ------------------------------------------------------------------

void InterpretedRules::writeSet(std::size_t rule, std::size_t daughter, rt::Match m, rt::WriteSet& w) const {
    const ir::Rule& r = st_.prog->rules[rule];
    const ir::Daughter& d = r.daughters[daughter];
    for (int n : d.deletedNodes) w.nodes.push_back(m.nodes[n]);
    for (int e : d.deletedEdges) w.edges.push_back(m.edges[e]);
    for (const auto& dn : d.nodes)
        if (dn.motherNode >= 0 && (dn.position || !dn.assigns.empty() || !dn.styles.empty()))
            w.nodes.push_back(m.nodes[dn.motherNode]);
    for (const auto& de : d.edges) {
        if (de.motherEdge < 0) continue;
        const auto& me = r.edges[de.motherEdge];
        const bool rewired = d.nodes[de.src].motherNode != me.src || d.nodes[de.dst].motherNode != me.dst;
        if (rewired || !de.assigns.empty() || !de.styles.empty()) w.edges.push_back(m.edges[de.motherEdge]);
    }
}

void InterpretedRules::evaluateValues(const std::vector<ir::AttrAssign>& attrs,
                                      const std::vector<ir::StyleAssign>& styles, EvalFrame& f, Values& v) {
    v.attrs.clear();
    v.styles.clear();
    for (const auto& a : attrs) v.attrs.emplace_back(a.attr, evaluate(a.value, f));
    for (const auto& s : styles) v.styles.emplace_back(static_cast<rt::StyleProp>(s.propId), evaluate(s.value, f));
}

void InterpretedRules::prepare(std::size_t rule, std::size_t daughter, rt::Match m, const rt::Graph& g,
                               rt::Rng& rng, long long) {
    const ir::Rule& r = st_.prog->rules[rule];
    const ir::Daughter& d = r.daughters[daughter];
    current_ = &r;
    locals_.assign(static_cast<std::size_t>(r.localSlots), rt::Value{});
    EvalFrame f = st_.frame(&rng);
    f.graph = &g;
    f.nodes = m.nodes;
    f.edges = m.edges;
    f.locals = &locals_;
    for (const auto& l : r.lets) locals_[l.slot] = evaluate(l.value, f);
    for (const auto& l : d.lets) locals_[l.slot] = evaluate(l.value, f);

    if (pendingCount_ == pending_.size()) pending_.emplace_back();
    Prepared& p = pending_[pendingCount_];
    p.rule = rule;
    p.daughter = daughter;
    p.nodes.assign(m.nodes, m.nodes + r.nodes.size());
    p.edges.assign(m.edges, m.edges + r.edges.size());
    p.nodePos.clear();
    p.nodeValues.resize(d.nodes.size());
    p.edgeValues.resize(d.edges.size());
    // Automatic positions first: `at` may refine them through `placed`.
    auto& placed = placed_;
    placed.assign(d.nodes.size(), std::nullopt);
    if (d.autoPlacement) {
        std::vector<rt::vec2> mother, host, refDaughter, refHost;
        for (std::size_t i = 0; i < r.nodes.size(); ++i) {
            mother.push_back({r.nodes[i].sketch->x, r.nodes[i].sketch->y});
            host.push_back(g.pos(m.nodes[i]));
        }
        for (const auto& dn : d.nodes)
            if (dn.motherNode >= 0) {
                refDaughter.push_back({dn.sketch->x, dn.sketch->y});
                refHost.push_back(host[dn.motherNode]);
            }
        if (refDaughter.empty()) {
            refDaughter = mother;
            refHost = host;
        }
        std::optional<std::pair<int, int>> directed;
        for (const auto& e : r.edges)
            if (st_.prog->kinds[e.kind].directed && e.src != e.dst) {
                directed = std::make_pair(e.src, e.dst);
                break;
            }
        const rt::PlacementFrame frame = rt::placementFrame(mother, host, directed, refDaughter, refHost);
        for (std::size_t i = 0; i < d.nodes.size(); ++i) {
            const auto& dn = d.nodes[i];
            if (dn.motherNode >= 0 || !dn.sketch) continue;
            const rt::vec2 pos = frame.place({dn.sketch->x, dn.sketch->y});
            if (!std::isfinite(pos.x) || !std::isfinite(pos.y))
                throw EvalError(dn.span, "automatic placement of `" + dn.name + "` gives a non-finite position");
            placed[i] = pos;
        }
    }
    f.placed = &placed;
    for (const auto& dn : d.nodes) {
        std::optional<rt::vec2> pos;
        if (dn.position) {
            pos = evaluateVec(*dn.position, f);
            if (!std::isfinite(pos->x) || !std::isfinite(pos->y))
                throw EvalError(dn.position->span, "position of `" + dn.name + "` is not finite");
        }
        p.nodePos.push_back(pos);
        evaluateValues(dn.assigns, dn.styles, f, p.nodeValues[&dn - d.nodes.data()]);
    }
    for (std::size_t i = 0; i < d.edges.size(); ++i) evaluateValues(d.edges[i].assigns, d.edges[i].styles, f, p.edgeValues[i]);
    for (std::size_t i = 0; i < d.nodes.size(); ++i)
        if (!p.nodePos[i] && d.nodes[i].motherNode < 0) p.nodePos[i] = placed[i];
    ++pendingCount_;
}

// The order of a rewrite: deleted edges go; new nodes come; kept edges that
// change ends are reconnected (before their old end nodes go, so they
// survive); deleted nodes go with their remaining edges; then kept nodes
// change, and edges are updated or created, in the daughter's order.
void InterpretedRules::commit(rt::Graph& g, long long step) {
    for (std::size_t k = 0; k < pendingCount_; ++k) {
        Prepared& p = pending_[k];
        const ir::Rule& r = st_.prog->rules[p.rule];
        const ir::Daughter& d = r.daughters[p.daughter];
        for (int e : d.deletedEdges) g.removeEdge(p.edges[e]);
        auto& hostOf = hostOf_;
        hostOf.assign(d.nodes.size(), kNoId);
        for (std::size_t i = 0; i < d.nodes.size(); ++i) {
            const auto& dn = d.nodes[i];
            if (dn.motherNode >= 0) {
                hostOf[i] = p.nodes[dn.motherNode];
                continue;
            }
            hostOf[i] = g.addNode(dn.kind, *p.nodePos[i], step);
            for (auto& [attr, v] : p.nodeValues[i].attrs) g.setNodeAttr(hostOf[i], attr, std::move(v));
        }
        for (const auto& de : d.edges) {
            if (de.motherEdge < 0) continue;
            const auto& me = r.edges[de.motherEdge];
            if (d.nodes[de.src].motherNode != me.src || d.nodes[de.dst].motherNode != me.dst)
                g.reconnectEdge(p.edges[de.motherEdge], hostOf[de.src], hostOf[de.dst]);
        }
        for (int n : d.deletedNodes) g.removeNode(p.nodes[n]);
        for (std::size_t i = 0; i < d.nodes.size(); ++i) {
            const auto& dn = d.nodes[i];
            auto& values = p.nodeValues[i];
            if (dn.motherNode >= 0) {
                if (p.nodePos[i]) g.setPos(hostOf[i], *p.nodePos[i]);
                for (auto& [attr, v] : values.attrs) g.setNodeAttr(hostOf[i], attr, std::move(v));
            }
            for (auto& [prop, v] : values.styles) g.setNodeStyle(hostOf[i], prop, std::move(v));
        }
        for (std::size_t i = 0; i < d.edges.size(); ++i) {
            const auto& de = d.edges[i];
            auto& values = p.edgeValues[i];
            EdgeId h;
            if (de.motherEdge >= 0) {
                h = p.edges[de.motherEdge];
                for (auto& [attr, v] : values.attrs) g.setEdgeAttr(h, attr, std::move(v));
            } else {
                h = g.addEdge(de.kind, hostOf[de.src], hostOf[de.dst], step);
                for (auto& [attr, v] : values.attrs) g.initEdgeAttr(h, attr, std::move(v));
            }
            for (auto& [prop, v] : values.styles) g.setEdgeStyle(h, prop, std::move(v));
        }
    }
    pendingCount_ = 0;
}

}  // namespace g2d::interp
