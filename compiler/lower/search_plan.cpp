#include "lower/search_plan.hpp"

#include "lower/fact_reads.hpp"

#include "lower/near_negative.hpp"

#include <algorithm>
#include <set>

#include "g2d/derivation.hpp"

namespace g2d::lower {


std::vector<int> faceSlots(const ir::PatternFace& f) { return f.corners.empty() ? std::vector<int>{f.anchor} : f.corners; }

std::vector<PlanStep> buildSearchPlan(const std::vector<ir::PatternNode>& nodes,
                                      const std::vector<ir::PatternEdge>& edges,
                                      const std::vector<ir::PatternFace>& faces,
                                      const std::vector<ir::Condition>& conditions, int nodeBase, int edgeBase,
                                      int boundOuterNodes, int anchor, int faceBase) {
    std::vector<PlanStep> plan;
    std::set<int> boundNodes;
    for (int i = 0; i < boundOuterNodes; ++i) boundNodes.insert(i);
    if (anchor >= 0) boundNodes.insert(anchor);
    std::set<int> boundEdges;
    for (int i = 0; i < edgeBase; ++i) boundEdges.insert(i);
    std::set<int> boundFaces;
    for (int i = 0; i < faceBase; ++i) boundFaces.insert(i);
    std::vector<bool> conditionPlaced(conditions.size(), false);

    auto isBound = [&](const ir::ElemRef& r) {
        return r.cls == ir::ElemClass::Node ? boundNodes.count(r.index) > 0
               : r.cls == ir::ElemClass::Edge ? boundEdges.count(r.index) > 0
                                              : boundFaces.count(r.index) > 0;
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
    const std::size_t total = nodes.size() + edges.size() + faces.size();
    std::size_t placed = anchor >= 0 ? 1 : 0;
    // Binds faces[fi] from node `from` (its corner `fromCorner`), or by scanning (-1).
    auto bindFace = [&](int fi, int from, int fromCorner) {
        PlanStep s;
        s.op = PlanStep::Op::BindFace;
        s.face = faceBase + fi;
        s.from = from;
        s.fromCorner = fromCorner;
        plan.push_back(s);
        boundFaces.insert(faceBase + fi);
        ++placed;
        for (int c : faceSlots(faces[static_cast<std::size_t>(fi)]))
            if (boundNodes.insert(c).second) ++placed;
    };
    while (placed < total) {
        bool progressed = false;
        // 0. A face with a bound corner: its few faces there, and its corners with them.
        for (std::size_t i = 0; i < faces.size() && !progressed; ++i) {
            if (boundFaces.count(faceBase + static_cast<int>(i))) continue;
            const std::vector<int> slots = faceSlots(faces[i]);
            for (std::size_t c = 0; c < slots.size() && !progressed; ++c)
                if (boundNodes.count(slots[c])) {
                    bindFace(static_cast<int>(i), slots[c], static_cast<int>(c));
                    progressed = true;
                }
        }
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
        // 3. Start a new component: a face (its kind's index, and it binds
        // its corners), else the typed node with the most incident edges.
        for (std::size_t i = 0; i < faces.size() && !progressed; ++i)
            if (!boundFaces.count(faceBase + static_cast<int>(i))) {
                bindFace(static_cast<int>(i), -1, -1);
                progressed = true;
            }
        if (!progressed) {
            int best = -1, bestScore = -1;
            for (std::size_t i = 0; i < nodes.size(); ++i) {
                const int ni = nodeBase + static_cast<int>(i);
                if (boundNodes.count(ni)) continue;
                // A node near bound ones first (a spatial lookup: lower::nearJoin;
                // a match's own nodes only), then typed nodes, then nodes with
                // their own conditions (they prune before any walking), then the best connected.
                const bool near = nodeBase == 0 && !boundNodes.empty() &&
                                  nearJoin(conditions, nodes[i], ni, [&](int n) { return boundNodes.count(n) > 0; });
                const int score = (near ? 10000 : 0) + (nodes[i].kind >= 0 ? 1000 : 0) + (ownConditions(ni) ? 100 : 0) + degree(ni);
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

namespace {

// The elements a negative condition's conditions read (node and edge indices).
void collectReads(const ir::Expr& e, std::vector<int>& nodes, std::vector<int>& edges) {
    if (e.op == ir::ExprOp::Attr || e.op == ir::ExprOp::Fact)
        (e.elem.cls == ir::ElemClass::Edge ? edges : nodes).push_back(e.elem.index);
    for (const auto& a : e.args) collectReads(a, nodes, edges);
}

}  // namespace

int repairRadius(const ir::Rule& rule) {
    // A change reaches a match through a negative condition's own nodes only
    // when a condition reads such a node (or an edge between two of them),
    // or an edge between two of them changes; changes on an edge from a match
    // node are seen at that node (incidenceReaders). The radius is the depth
    // (in edges from the match) of the shallowest end of what is read.
    int radius = 0;
    const int outer = static_cast<int>(rule.nodes.size());
    for (std::size_t k = 0; k < rule.nacs.size(); ++k) {
        // A node near a point: the spatial index tells repair which matches to revisit.
        if (nearNegative(rule, k)) continue;
        const auto& nac = rule.nacs[k];
        const int total = outer + static_cast<int>(nac.nodes.size());
        auto valid = [&](const ir::PatternEdge& e) { return e.src >= 0 && e.dst >= 0 && e.src < total && e.dst < total; };
        std::vector<int> depth(static_cast<std::size_t>(total), -1);
        for (int i = 0; i < outer; ++i) depth[static_cast<std::size_t>(i)] = 0;
        // A face joins its corners, as an edge its ends (repair walks both).
        for (const auto& f : nac.faces)
            if (f.corners.empty()) return -1;   // any face of its kind, anywhere
        auto validNode = [&](int n) { return n >= 0 && n < total; };
        for (bool grew = true; grew;) {
            grew = false;
            for (const auto& e : nac.edges) {
                if (!valid(e)) continue;  // after an error
                auto& a = depth[static_cast<std::size_t>(e.src)];
                auto& b = depth[static_cast<std::size_t>(e.dst)];
                if (a >= 0 && (b < 0 || b > a + 1)) { b = a + 1; grew = true; }
                if (b >= 0 && (a < 0 || a > b + 1)) { a = b + 1; grew = true; }
            }
            for (const auto& f : nac.faces) {
                int nearest = -1;
                for (int c : f.corners)
                    if (validNode(c) && depth[static_cast<std::size_t>(c)] >= 0 &&
                        (nearest < 0 || depth[static_cast<std::size_t>(c)] < nearest))
                        nearest = depth[static_cast<std::size_t>(c)];
                if (nearest < 0) continue;
                for (int c : f.corners) {
                    if (!validNode(c)) continue;
                    auto& d = depth[static_cast<std::size_t>(c)];
                    if (d < 0 || d > nearest + 1) { d = nearest + 1; grew = true; }
                }
            }
        }
        for (int d : depth)
            if (d < 0) return -1;   // a part not connected to the match
        auto at = [&](int node) { return depth[static_cast<std::size_t>(node)]; };
        std::vector<int> readNodes, readEdges;
        for (const auto& c : nac.conditions) collectReads(c.expr, readNodes, readEdges);
        for (int n : readNodes)
            if (n >= outer && n < total) radius = std::max(radius, at(n));
        for (int i : readEdges) {
            const int k = i - nac.outerEdges;
            if (k >= 0 && k < static_cast<int>(nac.edges.size()) && valid(nac.edges[static_cast<std::size_t>(k)]))
                radius = std::max(radius, std::min(at(nac.edges[static_cast<std::size_t>(k)].src), at(nac.edges[static_cast<std::size_t>(k)].dst)));
        }
        for (const auto& e : nac.edges)
            if (valid(e) && e.src >= outer && e.dst >= outer) radius = std::max(radius, std::min(at(e.src), at(e.dst)));
        // A face changes for a match at any of its corners (its first corner,
        // when it moves or its attributes are written; all when it comes or goes).
        for (const auto& f : nac.faces)
            for (int c : f.corners)
                if (validNode(c)) radius = std::max(radius, at(c));
    }
    return radius;
}

namespace {

// Facts reading the edges at a node (degrees) read every edge there; an
// edge's read every edge at its ends.
void markDegreeReads(const ir::Expr& expr, const ir::Rule& rule, std::vector<bool>& reads) {
    const int matchNodes = static_cast<int>(rule.nodes.size());
    eachFact(expr, [&](const ir::Expr& e, std::uint8_t factReads) {
        if (!(factReads & rt::kReadsEdgesAt)) return;
        if (e.elem.cls == ir::ElemClass::Node && e.elem.index < matchNodes) reads[static_cast<std::size_t>(e.elem.index)] = true;
        if (e.elem.cls == ir::ElemClass::Edge && e.elem.index < static_cast<int>(rule.edges.size()))
            for (int end : {rule.edges[static_cast<std::size_t>(e.elem.index)].src, rule.edges[static_cast<std::size_t>(e.elem.index)].dst})
                if (end >= 0 && end < matchNodes) reads[static_cast<std::size_t>(end)] = true;
    });
}

}  // namespace

std::vector<rt::Incidence> incidenceReaders(const ir::Rule& rule) {
    const int outer = static_cast<int>(rule.nodes.size());
    std::vector<bool> all(rule.nodes.size(), false);
    // Forced: degrees read in conditions, and edges to a negative condition's
    // own nodes (only this end sees them change).
    for (const auto& c : rule.conditions) markDegreeReads(c.expr, rule, all);
    // Edges between two match nodes: the pattern's, and negative conditions'.
    std::vector<std::pair<int, int>> own, forbidden;
    const auto valid = [&](int i, int limit) { return i >= 0 && i < limit; };  // not after an error
    for (const auto& e : rule.edges)
        if (valid(e.src, outer) && valid(e.dst, outer)) own.emplace_back(e.src, e.dst);
    for (const auto& nac : rule.nacs) {
        for (const auto& c : nac.conditions) markDegreeReads(c.expr, rule, all);
        const int total = outer + static_cast<int>(nac.nodes.size());
        for (const auto& e : nac.edges) {
            if (!valid(e.src, total) || !valid(e.dst, total)) continue;
            const bool srcOuter = e.src < outer, dstOuter = e.dst < outer;
            if (srcOuter && dstOuter) forbidden.emplace_back(e.src, e.dst);
            else if (srcOuter) all[static_cast<std::size_t>(e.src)] = true;
            else if (dstOuter) all[static_cast<std::size_t>(e.dst)] = true;
        }
    }
    // An edge between two match nodes changes both ends' incidences: one
    // reading end suffices. Cover them greedily, preferring ends already
    // reading, then the end with more such edges, then the lower index. A
    // negative condition's edge needs an end reading every edge (the edge is
    // not the match's); the pattern's own, any reading end (a match binding
    // a removed edge is dropped, one binding a new edge is found).
    std::vector<int> count(rule.nodes.size(), 0);
    for (const auto* list : {&forbidden, &own})
        for (auto [a, b] : *list) {
            ++count[static_cast<std::size_t>(a)];
            if (b != a) ++count[static_cast<std::size_t>(b)];
        }
    const auto cover = [&](const std::vector<std::pair<int, int>>& edges, std::vector<bool>& reads) {
        for (auto [a, b] : edges) {
            if (reads[static_cast<std::size_t>(a)] || reads[static_cast<std::size_t>(b)]) continue;
            const int pick = count[static_cast<std::size_t>(b)] > count[static_cast<std::size_t>(a)] ? b : a;
            reads[static_cast<std::size_t>(pick)] = true;
        }
    };
    cover(forbidden, all);
    std::vector<bool> any = all;
    cover(own, any);
    std::vector<rt::Incidence> reads;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i)
        reads.push_back(all[i] ? rt::Incidence::AllEdges : any[i] ? rt::Incidence::PatternEdges : rt::Incidence::None);
    return reads;
}

std::vector<std::uint8_t> incidenceDirections(const ir::Rule& rule, const std::vector<bool>& directed,
                                              const std::vector<rt::Incidence>& reads) {
    std::vector<std::uint8_t> dirs(rule.nodes.size(), 0);
    const int outer = static_cast<int>(rule.nodes.size());
    const std::uint8_t both = rt::RepairArea::kOut | rt::RepairArea::kIn;
    for (const auto& e : rule.edges) {
        if (e.src < 0 || e.dst < 0 || e.src >= outer || e.dst >= outer) continue;
        const bool oneWay = e.kind >= 0 && static_cast<std::size_t>(e.kind) < directed.size() &&
                            directed[static_cast<std::size_t>(e.kind)] && e.src != e.dst;
        dirs[static_cast<std::size_t>(e.src)] |= oneWay ? rt::RepairArea::kOut : both;
        dirs[static_cast<std::size_t>(e.dst)] |= oneWay ? rt::RepairArea::kIn : both;
    }
    for (std::size_t i = 0; i < dirs.size(); ++i) {
        if (reads[i] == rt::Incidence::None) dirs[i] = 0;
        else if (reads[i] == rt::Incidence::AllEdges || dirs[i] == 0) dirs[i] = both;
    }
    return dirs;
}

std::vector<bool> newHostsAddingNothing(const ir::Rule& rule, const std::vector<rt::Incidence>& reads) {
    const int outer = static_cast<int>(rule.nodes.size());
    std::vector<bool> nothing(rule.nodes.size(), false);
    for (const auto& e : rule.edges) {
        if (e.src < 0 || e.dst < 0 || e.src >= outer || e.dst >= outer) continue;
        const int first = std::min(e.src, e.dst), later = std::max(e.src, e.dst);
        if (first < later && reads[static_cast<std::size_t>(first)] != rt::Incidence::None)
            nothing[static_cast<std::size_t>(later)] = true;
    }
    return nothing;
}

std::vector<std::vector<int>> edgeKindsNeeded(const ir::Rule& rule, int edgeKinds) {
    std::vector<std::vector<int>> needed(rule.nodes.size());
    if (edgeKinds <= 1) return needed;
    const int outer = static_cast<int>(rule.nodes.size());
    for (const auto& e : rule.edges) {
        if (e.kind < 0) continue;
        for (int end : {e.src, e.dst}) {
            if (end < 0 || end >= outer) continue;   // after an error
            auto& kinds = needed[static_cast<std::size_t>(end)];
            if (std::find(kinds.begin(), kinds.end(), e.kind) == kinds.end()) kinds.push_back(e.kind);
        }
    }
    return needed;
}

}  // namespace g2d::lower
