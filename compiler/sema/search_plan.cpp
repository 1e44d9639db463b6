#include "sema/search_plan.hpp"

#include <algorithm>
#include <set>

namespace g2d::sema {

using ir::PlanStep;

std::vector<PlanStep> buildSearchPlan(const std::vector<ir::PatternNode>& nodes,
                                      const std::vector<ir::PatternEdge>& edges,
                                      const std::vector<ir::Condition>& conditions, int nodeBase, int edgeBase,
                                      int boundOuterNodes, int anchor) {
    std::vector<PlanStep> plan;
    std::set<int> boundNodes;
    for (int i = 0; i < boundOuterNodes; ++i) boundNodes.insert(i);
    if (anchor >= 0) boundNodes.insert(anchor);
    std::set<int> boundEdges;
    for (int i = 0; i < edgeBase; ++i) boundEdges.insert(i);
    std::vector<bool> conditionPlaced(conditions.size(), false);

    auto isBound = [&](const ir::ElemRef& r) {
        return r.cls == ir::ElemClass::Node ? boundNodes.count(r.index) > 0 : boundEdges.count(r.index) > 0;
    };
    auto placeConditions = [&]() {
        for (std::size_t c = 0; c < conditions.size(); ++c) {
            if (conditionPlaced[c]) continue;
            bool ready = true;
            for (const auto& d : conditions[c].deps) ready = ready && isBound(d);
            if (!ready) continue;
            conditionPlaced[c] = true;
            PlanStep s;
            s.op = PlanStep::Op::Check;
            s.condition = static_cast<int>(c);
            plan.push_back(s);
        }
    };
    auto degree = [&](int node) {
        int d = 0;
        for (const auto& e : edges) d += (e.src == node) + (e.dst == node);
        return d;
    };

    auto ownConditions = [&](int node) {
        for (const auto& c : conditions)
            if (c.deps.size() == 1 && c.deps[0] == ir::ElemRef{ir::ElemClass::Node, node}) return true;
        return false;
    };

    placeConditions();
    const std::size_t total = nodes.size() + edges.size();
    std::size_t placed = anchor >= 0 ? 1 : 0;
    while (placed < total) {
        bool progressed = false;
        // 1. An edge between two bound nodes: a lookup, no new candidates.
        for (std::size_t i = 0; i < edges.size() && !progressed; ++i) {
            const int ei = edgeBase + static_cast<int>(i);
            if (boundEdges.count(ei)) continue;
            const auto& e = edges[i];
            if (boundNodes.count(e.src) && boundNodes.count(e.dst)) {
                PlanStep s;
                s.op = PlanStep::Op::ConnectEdge;
                s.edge = ei;
                s.from = e.src;
                s.node = e.dst;
                plan.push_back(s);
                boundEdges.insert(ei);
                ++placed;
                progressed = true;
            }
        }
        // 2. Walk from a bound node along an edge; typed far ends before wildcards.
        for (int pass = 0; pass < 2 && !progressed; ++pass) {
            for (std::size_t i = 0; i < edges.size() && !progressed; ++i) {
                const int ei = edgeBase + static_cast<int>(i);
                if (boundEdges.count(ei)) continue;
                const auto& e = edges[i];
                const bool srcBound = boundNodes.count(e.src) > 0, dstBound = boundNodes.count(e.dst) > 0;
                if (srcBound == dstBound) continue;
                const int far = srcBound ? e.dst : e.src;
                const bool farIsWildcard = far >= nodeBase && nodes[far - nodeBase].kind < 0;
                if (pass == 0 && farIsWildcard) continue;
                PlanStep s;
                s.op = PlanStep::Op::ExtendEdge;
                s.edge = ei;
                s.from = srcBound ? e.src : e.dst;
                s.node = far;
                s.fromIsSource = srcBound;
                plan.push_back(s);
                boundEdges.insert(ei);
                boundNodes.insert(far);
                placed += 2;
                progressed = true;
            }
        }
        // 3. Start a new component: the typed node with the most incident edges.
        if (!progressed) {
            int best = -1, bestScore = -1;
            for (std::size_t i = 0; i < nodes.size(); ++i) {
                const int ni = nodeBase + static_cast<int>(i);
                if (boundNodes.count(ni)) continue;
                // Typed nodes first, then nodes with their own conditions (they prune
                // before any walking), then the best connected.
                const int score = (nodes[i].kind >= 0 ? 1000 : 0) + (ownConditions(ni) ? 100 : 0) + degree(ni);
                if (score > bestScore) { bestScore = score; best = ni; }
            }
            if (best < 0) break;  // only edges with unknown endpoints remain (already reported)
            PlanStep s;
            s.op = PlanStep::Op::ScanNodes;
            s.node = best;
            plan.push_back(s);
            boundNodes.insert(best);
            ++placed;
        }
        placeConditions();
    }
    return plan;
}

int repairRadius(const ir::Rule& rule) {
    // Breadth-first over each negative condition's edges, from the match's
    // nodes (all at depth 0).
    int radius = 0;
    const int outer = static_cast<int>(rule.nodes.size());
    for (const auto& nac : rule.nacs) {
        const int total = outer + static_cast<int>(nac.nodes.size());
        std::vector<int> depth(static_cast<std::size_t>(total), -1);
        for (int i = 0; i < outer; ++i) depth[static_cast<std::size_t>(i)] = 0;
        for (bool grew = true; grew;) {
            grew = false;
            for (const auto& e : nac.edges) {
                auto& a = depth[static_cast<std::size_t>(e.src)];
                auto& b = depth[static_cast<std::size_t>(e.dst)];
                if (a >= 0 && (b < 0 || b > a + 1)) { b = a + 1; grew = true; }
                if (b >= 0 && (a < 0 || a > b + 1)) { a = b + 1; grew = true; }
            }
        }
        for (int d : depth) {
            if (d < 0) return -1;
            radius = std::max(radius, d);
        }
    }
    return radius;
}

}  // namespace g2d::sema
