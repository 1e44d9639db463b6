#include "interp/interpreted_rules.hpp"

#include <algorithm>
#include <cmath>

namespace g2d::interp {

using rt::EdgeId;
using rt::kNoId;
using rt::NodeId;

InterpretedRules::InterpretedRules(const ProgramState& st) : st_(st), lowered_(*st.lowered) {
    setTracksGenerations(st.program().tracksGenerations);
    std::size_t maxNodes = 0, maxEdges = 0, maxFaces = 0;
    for (const auto& rule : lowered_.rules) {
        const lower::RuleFacts& facts = rule.facts;
        rt::RuleInfo& info = infos_.emplace_back(facts.info);
        for (const lower::SetRuleNumber& n : facts.startNumbers) {
            const double v = checkedNumber(*n.value, nullptr, n.check.check);
            switch (n.field) {
            case lower::SetRuleNumber::Field::DaughterWeight: info.weights[static_cast<std::size_t>(n.daughter)] = v; break;
            case lower::SetRuleNumber::Field::ChoiceWeight: info.choiceWeight = v; break;
            case lower::SetRuleNumber::Field::MergeTolerance: info.mergeTolerance = v; break;
            }
        }
        const lower::MatchProgram& m = rule.match;
        maxNodes = std::max(maxNodes, static_cast<std::size_t>(m.nodeSlots));
        maxEdges = std::max(maxEdges, static_cast<std::size_t>(m.edgeSlots));
        maxFaces = std::max(maxFaces, static_cast<std::size_t>(m.faceSlots));
    }
    boundNodes_.assign(maxNodes, kNoId);
    boundEdges_.assign(maxEdges, kNoId);
    boundFaces_.assign(maxFaces, kNoId);
}

// ---- `layout angles`' cost ---------------------------------------------------------

bool InterpretedRules::hasDrawingCost() const { return st_.program().angleLayout && st_.program().angleLayout->cost; }

double InterpretedRules::drawingCost(const rt::KindCounts& counts) {
    return checkedNumber(*st_.program().angleLayout->cost, &counts, rt::checkedCost);
}

double InterpretedRules::drawingTemperature() {
    const auto& layout = st_.program().angleLayout;
    return layout && layout->temperature ? checkedNumber(*layout->temperature, nullptr, rt::checkedTemperature) : 1;
}

// A number of parameters and constants (and a cost's counts), as `check` accepts it; its failure is placed at `e`.
double InterpretedRules::checkedNumber(const ir::Expr& e, const rt::KindCounts* counts, double (*check)(double)) const {
    EvalFrame f = st_.frame(nullptr);
    f.counts = counts;
    try {
        return check(std::get<double>(evaluate(e, f)));
    } catch (const rt::OpError& err) {
        throw EvalError(e.span, err.what());
    }
}

// ---- matching: the lowered match lists, operation by operation -------------------

bool InterpretedRules::orderedOk(const rt::Graph& g, int node, const std::vector<lower::OrderCheck>& checks) const {
    if (checks.empty()) return true;
    const rt::vec2 hi = g.pos(boundNodes_[node]);
    for (const auto& c : checks) {
        const rt::vec2 hj = g.pos(boundNodes_[c.other]);
        const double a = c.axis == 0 ? hi.x : hi.y, b = c.axis == 0 ? hj.x : hj.y;
        if (c.before ? a > b : a < b) return false;
    }
    return true;
}

bool InterpretedRules::keptByNewEdgeGate(bool gateHere) const {
    if (!gateHere || newEdgesFrom_ == kNoId) return true;
    for (std::size_t k = 0; k < current_->edges.size(); ++k)
        if (boundEdges_[k] >= newEdgesFrom_) return true;
    return false;
}

EvalFrame InterpretedRules::boundFrame(const rt::Graph& g) {
    EvalFrame f = st_.frame(nullptr);
    f.graph = &g;
    f.nodes = boundNodes_.data();
    f.edges = boundEdges_.data();
    f.faces = boundFaces_.data();
    return f;
}

template <class OnComplete>
bool InterpretedRules::search(const rt::Graph& g, const lower::MatchList& ops, std::size_t i, OnComplete& onComplete) {
    if (i == ops.size()) return onComplete();
    auto usedNode = [&](const std::vector<int>& slots, NodeId h) {
        for (int s : slots)
            if (boundNodes_[s] == h) return true;
        return false;
    };
    auto usedEdge = [&](const std::vector<int>& slots, EdgeId e) {
        for (int s : slots)
            if (boundEdges_[s] == e) return true;
        return false;
    };
    return std::visit(
        lower::Overloaded{
            [&](const lower::Filter& o) {
                EvalFrame f = boundFrame(g);
                return evaluateBool(*o.condition, f) && search(g, ops, i + 1, onComplete);
            },
            [&](const lower::MatchFace& o) { return bindFace(g, o, ops, i, onComplete); },
            [&](const lower::ScanNear& o) {
                EvalFrame f = boundFrame(g);
                const rt::Value centre = evaluate(*o.centre, f);
                const rt::Value r = evaluate(*o.radius, f);   // an int or a float
                const double radius = std::holds_alternative<long long>(r) ? static_cast<double>(std::get<long long>(r)) : std::get<double>(r);
                const rt::vec3 at = std::holds_alternative<rt::vec3>(centre) ? std::get<rt::vec3>(centre)
                                                                             : rt::vec3(std::get<rt::vec2>(centre), 0.0);
                // A join's list is copied: a later piece's join asks again while this one is walked.
                const auto found = o.join ? nearQueries().nodesAround(g, o.kind, at, radius)
                                          : nearQueries().nodesNear(g, currentIndex_, o.near, boundNodes_[o.key], o.kind, at, radius);
                const std::vector<NodeId> copy = o.join ? std::vector<NodeId>(found.begin(), found.end()) : std::vector<NodeId>{};
                const std::span<const NodeId> near = o.join ? std::span<const NodeId>(copy) : found;
                for (const NodeId h : near) {
                    if (usedNode(o.distinctNodes, h) || (g.edgeKindsAt(h) & o.edgeKinds) != o.edgeKinds) continue;
                    boundNodes_[o.node] = h;
                    const bool stop = search(g, ops, i + 1, onComplete);
                    boundNodes_[o.node] = kNoId;
                    if (stop) return true;
                }
                return false;
            },
            [&](const lower::ScanNodes& o) {
                auto tryHost = [&](NodeId h) {
                    if (usedNode(o.distinctNodes, h) || (g.edgeKindsAt(h) & o.edgeKinds) != o.edgeKinds) return false;
                    boundNodes_[o.node] = h;
                    const bool stop = orderedOk(g, o.node, o.ordered) && search(g, ops, i + 1, onComplete);
                    boundNodes_[o.node] = kNoId;
                    return stop;
                };
                if (o.kind < 0) {
                    for (NodeId h : g.allNodes())
                        if (tryHost(h)) return true;
                    return false;
                }
                const auto candidates = g.nodesOfKind(o.kind);
                for (std::size_t c = 0; c < candidates.size(); ++c)
                    if (tryHost(candidates[c])) return true;
                return false;
            },
            [&](const lower::ExtendEdge& o) {
                const NodeId from = boundNodes_[o.from];
                auto tryEdge = [&](EdgeId e) {
                    if (g.edgeKind(e) != o.kind || usedEdge(o.distinctEdges, e)) return false;
                    if (o.directed && (o.fromIsSource ? g.source(e) != from : g.target(e) != from)) return false;
                    const NodeId other = g.source(e) == from ? g.target(e) : g.source(e);
                    if ((o.nodeKind >= 0 && g.nodeKind(other) != o.nodeKind) || usedNode(o.distinctNodes, other)) return false;
                    boundEdges_[o.edge] = e;
                    boundNodes_[o.node] = other;
                    const bool stop = keptByNewEdgeGate(o.newEdgeGate) && orderedOk(g, o.node, o.ordered) &&
                                      search(g, ops, i + 1, onComplete);
                    boundNodes_[o.node] = kNoId;
                    boundEdges_[o.edge] = kNoId;
                    return stop;
                };
                return eachEdgeAt(g, from, o.directed, o.fromIsSource, tryEdge);
            },
            [&](const lower::ConnectEdge& o) {
                const NodeId from = boundNodes_[o.from], to = boundNodes_[o.to];
                auto tryEdge = [&](EdgeId e) {
                    if (g.edgeKind(e) != o.kind || usedEdge(o.distinctEdges, e)) return false;
                    const NodeId a = g.source(e), b = g.target(e);
                    const bool fits = o.directed ? (a == from && b == to) : ((a == from && b == to) || (a == to && b == from));
                    if (!fits) return false;
                    boundEdges_[o.edge] = e;
                    const bool stop = keptByNewEdgeGate(o.newEdgeGate) && search(g, ops, i + 1, onComplete);
                    boundEdges_[o.edge] = kNoId;
                    return stop;
                };
                return eachEdgeAt(g, from, o.directed, true, tryEdge);
            },
        },
        ops[i]);
}

template <class OnComplete>
bool InterpretedRules::bindFace(const rt::Graph& g, const lower::MatchFace& o, const lower::MatchList& ops, std::size_t i,
                                OnComplete& onComplete) {
    const int k = static_cast<int>(o.corners.size());
    // Binds face f with `start` (one of its corners) at pattern corner 0.
    auto tryRotation = [&](rt::FaceId f, rt::CornerId start) {
        rt::CornerId c = start;
        bool fits = true;
        for (int j = 0; j < k && fits; ++j, c = g.nextCorner(c)) {
            const NodeId h = g.cornerNode(c);
            const int slot = o.corners[static_cast<std::size_t>(j)];
            if (o.cornerBound[static_cast<std::size_t>(j)]) {
                fits = boundNodes_[slot] == h;
                continue;
            }
            const int kind = o.cornerKinds[static_cast<std::size_t>(j)];
            fits = (kind < 0 || g.nodeKind(h) == kind) &&
                   std::none_of(o.distinctNodes.begin(), o.distinctNodes.end(), [&](int s) { return boundNodes_[s] == h; });
            if (fits) boundNodes_[slot] = h;
        }
        bool stop = false;
        if (fits) {
            boundFaces_[o.face] = f;
            stop = search(g, ops, i + 1, onComplete);
            boundFaces_[o.face] = kNoId;
        }
        for (int j = 0; j < k; ++j)
            if (!o.cornerBound[static_cast<std::size_t>(j)]) boundNodes_[o.corners[static_cast<std::size_t>(j)]] = kNoId;
        return stop;
    };
    auto faceFits = [&](rt::FaceId f) {
        return g.faceKind(f) == o.kind && (o.anyCount || g.cornerCount(f) == k) &&
               std::none_of(o.distinctFaces.begin(), o.distinctFaces.end(), [&](int s) { return boundFaces_[s] == f; });
    };
    if (o.from < 0) {
        const auto faces = g.facesOfKind(o.kind);
        for (std::size_t x = 0; x < faces.size(); ++x) {
            const rt::FaceId f = faces[x];
            if (!faceFits(f)) continue;
            rt::CornerId start = g.firstCorner(f);
            for (int r = 0; r < (o.anyCount ? 1 : k); ++r, start = g.nextCorner(start))
                if (tryRotation(f, start)) return true;
        }
        return false;
    }
    for (rt::CornerId c = g.firstCornerAt(boundNodes_[o.from]); c != kNoId; c = g.nextCornerAt(c)) {
        const rt::FaceId f = g.cornerFace(c);
        if (!faceFits(f) || (o.anyCount && c != g.firstCorner(f))) continue;
        rt::CornerId start = c;
        for (int j = 0; j < o.fromCorner; ++j) start = g.prevCorner(start);
        if (tryRotation(f, start)) return true;
    }
    return false;
}

// The edges at `from` that may bind a pattern edge: a directed one among
// `from`'s outgoing (or incoming) edges only, an undirected one among both
// (outgoing first, self-loops once: they are on both lists). A directed
// self-loop can bind an incoming pattern edge too (its ends may be `dpo`
// wildcards sharing the node). Stops when `each` returns true.
template <class Each>
bool InterpretedRules::eachEdgeAt(const rt::Graph& g, NodeId from, bool directed, bool outgoing, Each& each) {
    if (!directed || outgoing)
        for (EdgeId e = g.firstOut(from); e != kNoId; e = g.nextOut(e))
            if (each(e)) return true;
    if (!directed || !outgoing)
        for (EdgeId e = g.firstIn(from); e != kNoId; e = g.nextIn(e))
            if ((directed || g.source(e) != g.target(e)) && each(e)) return true;
    return false;
}

bool InterpretedRules::negativesHold(const rt::Graph& g, const lower::MatchProgram& m) {
    auto found = [] { return true; };
    for (const auto& nac : m.negatives)
        if (search(g, nac, 0, found)) return false;
    return true;
}

void InterpretedRules::collect(const rt::Graph& g, const lower::MatchProgram& m, const lower::MatchList& ops,
                               rt::MatchBuffer& out) {
    auto record = [&] {
        if (negativesHold(g, m)) out.add(boundNodes_.data(), boundEdges_.data(), boundFaces_.data());
        return false;  // enumerate them all
    };
    search(g, ops, 0, record);
}

void InterpretedRules::findMatches(std::size_t rule, const rt::Graph& g, rt::MatchBuffer& out) {
    current_ = &st_.program().rules[rule];
    currentIndex_ = rule;
    const lower::MatchProgram& m = lowered_.rules[rule].match;
    collect(g, m, m.full, out);
}

void InterpretedRules::findAnchored(std::size_t rule, const rt::Graph& g, int node, rt::NodeId host,
                                    rt::MatchBuffer& out, rt::EdgeId newEdgesFrom) {
    const lower::MatchProgram& m = lowered_.rules[rule].match;
    const std::uint32_t need = m.anchorEdgeKinds[static_cast<std::size_t>(node)];
    if ((g.edgeKindsAt(host) & need) != need) return;
    current_ = &st_.program().rules[rule];
    currentIndex_ = rule;
    boundNodes_[node] = host;
    newEdgesFrom_ = newEdgesFrom;
    collect(g, m, m.anchored[static_cast<std::size_t>(node)], out);
    newEdgesFrom_ = kNoId;
    boundNodes_[node] = kNoId;
}

// ---- rewriting: the lowered rewrite programs, operation by operation ------------

void InterpretedRules::writeSet(std::size_t rule, std::size_t daughter, rt::Match m, rt::WriteSet& w) const {
    const lower::RewriteProgram& p = lowered_.rules[rule].daughters[daughter];
    for (int n : p.effects.writtenNodes) w.nodes.push_back(m.nodes[n]);
    for (int e : p.effects.writtenEdges) w.edges.push_back(m.edges[e]);
    for (int f : p.effects.writtenFaces) w.faces.push_back(m.faces[f]);
}

EvalFrame InterpretedRules::matchFrame(const ir::Rule& r, rt::Match m, const rt::Graph& g, rt::Rng& rng) {
    current_ = &r;
    locals_.assign(static_cast<std::size_t>(r.localSlots), rt::Value{});
    EvalFrame f = st_.frame(&rng);
    f.graph = &g;
    f.nodes = m.nodes;
    f.edges = m.edges;
    f.faces = m.faces;
    f.locals = &locals_;
    return f;
}

void InterpretedRules::weigh(std::size_t rule, rt::Match m, const rt::Graph& g, std::vector<double>& weights) {
    current_ = &st_.program().rules[rule];
    EvalFrame f = st_.frame(nullptr);   // no random draws: weights may have none
    f.graph = &g;
    f.nodes = m.nodes;
    f.edges = m.edges;
    f.faces = m.faces;
    const auto& each = lowered_.rules[rule].facts.matchWeights.weights;
    for (const auto& w : each) {
        try {
            weights[static_cast<std::size_t>(w.daughter)] = rt::checkedMatchWeight(std::get<double>(evaluate(*w.value, f)));
        } catch (const rt::OpError& e) {
            throw EvalError(w.value->span, e.what());
        }
    }
    try {
        rt::checkSomeWeight(weights);
    } catch (const rt::OpError& e) {
        throw EvalError(each.front().value->span, e.what());
    }
}

void InterpretedRules::prepare(std::size_t rule, std::size_t daughter, rt::Match m, const rt::Graph& g,
                               rt::Rng& rng, long long) {
    const ir::Rule& r = st_.program().rules[rule];
    const lower::RewriteProgram& program = lowered_.rules[rule].daughters[daughter];
    EvalFrame f = matchFrame(r, m, g, rng);

    if (pendingCount_ == pending_.size()) pending_.emplace_back();
    Prepared& p = pending_[pendingCount_];
    p.rule = rule;
    p.daughter = daughter;
    p.nodes.assign(m.nodes, m.nodes + r.nodes.size());
    p.edges.assign(m.edges, m.edges + r.edges.size());
    p.faces.assign(m.faces, m.faces + r.faces.size());
    p.registers.assign(program.registers.size(), rt::Value{});
    executor_.prepare(program, m, g, f, p.registers, p.loops);
    ++pendingCount_;
}

std::vector<rt::Value> InterpretedRules::compoundValues(std::size_t compound, rt::Match m, const rt::Graph& g, rt::Rng& rng) {
    const lower::CompoundLets& lets = lowered_.compoundLets[compound];
    EvalFrame f = matchFrame(st_.program().rules[static_cast<std::size_t>(lets.matchRule)], m, g, rng);
    std::vector<rt::Value> values;
    for (const lower::EvalLocal& l : lets.lets) {
        locals_[static_cast<std::size_t>(l.slot)] = evaluate(*l.value, f);
        values.push_back(locals_[static_cast<std::size_t>(l.slot)]);
    }
    return values;
}

void InterpretedRules::commit(rt::Graph& g, long long step) {
    for (std::size_t k = 0; k < pendingCount_; ++k) {
        Prepared& p = pending_[k];
        executor_.commit(lowered_.rules[p.rule].daughters[p.daughter], rt::Match{p.nodes.data(), p.edges.data(), p.faces.data()}, p.registers, p.loops,
                         g, step);
        applicationDone(g);
    }
    pendingCount_ = 0;
}

}  // namespace g2d::interp
