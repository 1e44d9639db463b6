#include <algorithm>

#include "g2d/graph.hpp"
#include "lower/match_program.hpp"
#include "lower/near_negative.hpp"
#include "lower/search_plan.hpp"

namespace g2d::lower {

namespace {

class MatchLowering {
public:
    MatchLowering(const ir::Program& prog, const ir::Rule& rule) : prog_(prog), r_(rule) {
        int edgeKinds = 0;
        for (const auto& k : prog.kinds) edgeKinds += k.cls == ir::ElemClass::Edge;
        neededEdgeKinds_ = lower::edgeKindsNeeded(rule, edgeKinds);
    }

    MatchProgram lower() {
        MatchProgram p;
        p.full = list(buildSearchPlan(r_.nodes, r_.edges, r_.faces, r_.conditions, 0, 0, 0), nullptr, {}, {});
        for (std::size_t a = 0; a < r_.nodes.size(); ++a) {
            const int anchor = static_cast<int>(a);
            p.anchored.push_back(list(buildSearchPlan(r_.nodes, r_.edges, r_.faces, r_.conditions, 0, 0, 0, anchor), nullptr, {anchor}, {}));
            p.anchorEdgeKinds.push_back(edgeKindsNeeded(anchor));
        }
        std::size_t nodes = r_.nodes.size(), edges = r_.edges.size();
        int nears = 0;
        for (std::size_t k = 0; k < r_.nacs.size(); ++k) {
            const ir::NegativeCondition& nac = r_.nacs[k];
            near_ = nearNegative(r_, k);
            nearIndex_ = near_ ? nears++ : -1;
            std::vector<int> outerNodes, outerEdges;
            for (int i = 0; i < nac.outerNodes; ++i) outerNodes.push_back(i);
            for (int i = 0; i < nac.outerEdges; ++i) outerEdges.push_back(i);
            const auto plan = buildSearchPlan(nac.nodes, nac.edges, nac.faces, nac.conditions, nac.outerNodes, nac.outerEdges,
                                              static_cast<int>(r_.nodes.size()), -1, nac.outerFaces);
            p.negatives.push_back(list(plan, &nac, outerNodes, outerEdges));
            near_.reset();
            nodes = std::max(nodes, r_.nodes.size() + nac.nodes.size());
            edges = std::max(edges, r_.edges.size() + nac.edges.size());
        }
        p.nodeSlots = static_cast<int>(std::max<std::size_t>(nodes, 1));
        p.edgeSlots = static_cast<int>(std::max<std::size_t>(edges, 1));
        std::size_t faces = r_.faces.size();
        for (const auto& nac : r_.nacs) faces = std::max(faces, r_.faces.size() + nac.faces.size());
        p.faceSlots = static_cast<int>(std::max<std::size_t>(faces, 1));
        return p;
    }

private:
    int nodeKind(int i, const ir::NegativeCondition* nac) const { return ir::slotNodeKind(r_, nac, i); }
    const ir::PatternEdge& edgeOf(int i, const ir::NegativeCondition* nac) const { return ir::slotEdge(r_, nac, i); }
    // The edge kinds every host of pattern node `p` has had (lower::edgeKindsNeeded).
    std::uint32_t edgeKindsNeeded(int p) const {
        std::uint32_t need = 0;
        if (static_cast<std::size_t>(p) < neededEdgeKinds_.size())
            for (int k : neededEdgeKinds_[static_cast<std::size_t>(p)]) need |= rt::Graph::edgeKindBit(k);
        return need;
    }
    // `ordered`, as the thesis's tool: a node drawn left of another must not
    // match one right of it (ties are allowed), and likewise for y; checked
    // against every pattern node bound before it.
    std::vector<OrderCheck> ordered(int k, const std::vector<int>& bound) const {
        std::vector<OrderCheck> out;
        if (!r_.ordered || k >= static_cast<int>(r_.nodes.size())) return out;
        const auto& si = *r_.nodes[k].sketch;
        for (int j : bound) {
            if (j >= static_cast<int>(r_.nodes.size())) continue;
            const auto& sj = *r_.nodes[j].sketch;
            if (si.x != sj.x) out.push_back(OrderCheck{j, 0, si.x < sj.x});
            if (si.y != sj.y) out.push_back(OrderCheck{j, 1, si.y < sj.y});
        }
        return out;
    }

    // The bound node slots a newly bound node must differ from: a face's
    // hidden anchor is no pattern node (any host may be a face's first corner).
    // In a `dpo` rule, two wildcards every daughter keeps may share a host
    // node (the identification condition: only preserved nodes may be identified).
    std::vector<int> distinct(int node, const std::vector<int>& bound, const ir::NegativeCondition* nac) const {
        std::vector<int> out;
        for (int n : bound)
            if (ir::slotNode(r_, nac, n).anchorOf < 0 && !(!nac && identifiable(node) && identifiable(n))) out.push_back(n);
        return out;
    }
    bool identifiable(int node) const {
        if (!r_.dpo || node < 0 || node >= static_cast<int>(r_.nodes.size())) return false;
        const ir::PatternNode& p = r_.nodes[static_cast<std::size_t>(node)];
        if (p.kind >= 0 || p.anchorOf >= 0) return false;
        for (const auto& d : r_.daughters)
            if (std::find(d.deletedNodes.begin(), d.deletedNodes.end(), node) != d.deletedNodes.end()) return false;
        return true;
    }

    MatchList list(const std::vector<PlanStep>& plan, const ir::NegativeCondition* nac, std::vector<int> boundNodes,
                   std::vector<int> boundEdges) const {
        MatchList out;
        std::vector<int> boundFaces;
        if (nac)
            for (int i = 0; i < nac->outerFaces; ++i) boundFaces.push_back(i);
        for (const auto& s : plan) {
            // A search keeping only matches that bind a new edge tests that
            // where the pattern's last edge is bound (not in negative conditions).
            const bool lastEdge = !nac && boundEdges.size() + 1 == r_.edges.size();
            switch (s.op) {
            case PlanStep::Op::Check: {
                const auto& cond = nac ? nac->conditions[s.condition] : r_.conditions[s.condition];
                out.push_back(Filter{&cond.expr});
                break;
            }
            case PlanStep::Op::ScanNodes:
                if (const auto join = nac || r_.ordered ? std::nullopt : nearJoin(r_.conditions, r_.nodes[static_cast<std::size_t>(s.node)], s.node, [&](int n) {
                        return std::find(boundNodes.begin(), boundNodes.end(), n) != boundNodes.end();
                    })) {
                    ScanNear o{s.node, join->kind, -1, join->key, join->centre, join->radius, distinct(s.node, boundNodes, nac)};
                    o.join = true;
                    o.edgeKinds = edgeKindsNeeded(s.node);
                    out.push_back(std::move(o));
                } else if (near_ && s.node == near_->node)
                    out.push_back(ScanNear{s.node, near_->kind, nearIndex_, near_->key, near_->centre, near_->radius, distinct(s.node, boundNodes, nac)});
                else
                    out.push_back(ScanNodes{s.node, nodeKind(s.node, nac), nac ? 0u : edgeKindsNeeded(s.node), distinct(s.node, boundNodes, nac),
                                        ordered(s.node, boundNodes)});
                boundNodes.push_back(s.node);
                break;
            case PlanStep::Op::ExtendEdge: {
                const auto& pe = edgeOf(s.edge, nac);
                out.push_back(ExtendEdge{s.edge, s.from, s.node, pe.kind, prog_.kinds[pe.kind].directed, s.fromIsSource,
                                         nodeKind(s.node, nac), boundEdges, distinct(s.node, boundNodes, nac), ordered(s.node, boundNodes), lastEdge});
                boundNodes.push_back(s.node);
                boundEdges.push_back(s.edge);
                break;
            }
            case PlanStep::Op::BindFace: {
                const ir::PatternFace& pf = ir::slotFace(r_, nac, s.face);
                MatchFace o{s.face, pf.kind, s.from, s.fromCorner, faceSlots(pf), pf.corners.empty(), {}, {},
                            pf.corners.empty() ? std::vector<int>{} : distinct(-1, boundNodes, nac), boundFaces};
                for (int c : o.corners) {
                    const bool bound = std::find(boundNodes.begin(), boundNodes.end(), c) != boundNodes.end();
                    o.cornerBound.push_back(bound ? 1 : 0);
                    o.cornerKinds.push_back(bound ? -1 : nodeKind(c, nac));
                }
                for (int c : o.corners)
                    if (std::find(boundNodes.begin(), boundNodes.end(), c) == boundNodes.end()) boundNodes.push_back(c);
                boundFaces.push_back(s.face);
                out.push_back(std::move(o));
                break;
            }
            case PlanStep::Op::ConnectEdge: {
                const auto& pe = edgeOf(s.edge, nac);
                out.push_back(ConnectEdge{s.edge, s.from, s.node, pe.kind, prog_.kinds[pe.kind].directed, boundEdges, lastEdge});
                boundEdges.push_back(s.edge);
                break;
            }
            }
        }
        return out;
    }

    const ir::Program& prog_;
    const ir::Rule& r_;
    std::optional<NearNegative> near_;   // the negative condition being lowered, when it is a node near a point
    int nearIndex_ = -1;
    std::vector<std::vector<int>> neededEdgeKinds_;   // per pattern node
};

}  // namespace

MatchProgram lowerMatch(const ir::Program& prog, const ir::Rule& rule) { return MatchLowering(prog, rule).lower(); }

}  // namespace g2d::lower
