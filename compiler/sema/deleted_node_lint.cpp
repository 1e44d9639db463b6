#include "sema/deleted_node_lint.hpp"

#include <algorithm>
#include <map>
#include <vector>

namespace g2d::sema {

namespace {

bool deletes(const ir::Daughter& d, int motherNode) {
    return std::find(d.deletedNodes.begin(), d.deletedNodes.end(), motherNode) != d.deletedNodes.end();
}

bool makesSomething(const ir::Daughter& d) {
    return std::any_of(d.nodes.begin(), d.nodes.end(), [](const auto& n) { return n.motherNode < 0; }) ||
           std::any_of(d.edges.begin(), d.edges.end(), [](const auto& e) { return e.motherEdge < 0; }) ||
           !d.faces.empty() || !d.loops.empty() || !d.splits.empty();
}

int daughterIndexOf(const ir::Daughter& d, int motherNode) {
    for (std::size_t i = 0; i < d.nodes.size(); ++i)
        if (d.nodes[i].motherNode == motherNode) return static_cast<int>(i);
    return -1;
}

// The daughter puts something in the deleted node's place: a new node of its
// kind, or a new edge of the joining edge's kind at the neighbour it kept.
bool replaces(const ir::Daughter& d, int kind, int neighbour, int edgeKind) {
    for (const auto& n : d.nodes)
        if (n.motherNode < 0 && n.kind == kind) return true;
    const int at = daughterIndexOf(d, neighbour);
    for (const auto& e : d.edges)
        if (e.motherEdge < 0 && e.kind == edgeKind && (e.src == at || e.dst == at)) return true;
    return false;
}

// Why the node looks forgotten in this daughter: the daughter makes something
// and keeps every node the match joins to it, but puts nothing in its place
// (when it deletes a neighbour too, it is taking a part of the graph apart).
// Returns a kept neighbour's mother index, or -1.
int forgottenNeighbour(const ir::Rule& r, const ir::Daughter& d, int node) {
    if (!deletes(d, node) || !makesSomething(d)) return -1;
    int kept = -1;
    for (const auto& e : r.edges) {
        if (e.src < 0 || e.dst < 0 || (e.src != node && e.dst != node)) continue;
        const int other = e.src == node ? e.dst : e.src;
        if (other == node) continue;
        if (deletes(d, other) || replaces(d, r.nodes[node].kind, other, e.kind)) return -1;
        if (kept < 0) kept = other;
    }
    return kept;
}

}  // namespace

void warnForgottenNodes(Globals& g) {
    const ir::Program& p = g.prog;
    // For each node kind, where rules' daughters keep a matched node of it
    // (the first such statement of each rule).
    struct Keeper { std::size_t rule; Span statement; };
    std::map<int, std::vector<Keeper>> keepers;
    for (std::size_t ri = 0; ri < p.rules.size(); ++ri)
        for (const auto& d : p.rules[ri].daughters)
            for (const auto& n : d.nodes) {
                if (n.motherNode < 0 || n.kind < 0) continue;
                auto& found = keepers[n.kind];
                if (found.empty() || found.back().rule != ri) found.push_back({ri, n.span});
            }
    for (std::size_t ri = 0; ri < p.rules.size(); ++ri) {
        const ir::Rule& r = p.rules[ri];
        if (r.span.file != g.mainFile || r.compound >= 0 || r.daughters.empty()) continue;
        for (std::size_t ni = 0; ni < r.nodes.size(); ++ni) {
            const auto& node = r.nodes[ni];
            if (node.kind < 0 || node.anchorOf >= 0) continue;
            // "Elsewhere": another rule keeps a matched node of this kind.
            const auto& found = keepers[node.kind];
            const auto keeper = std::find_if(found.begin(), found.end(), [&](const Keeper& k) { return k.rule != ri; });
            if (keeper == found.end()) continue;
            int neighbour = -1;
            bool everyDaughter = true;
            for (const auto& d : r.daughters) {
                const int joined = forgottenNeighbour(r, d, static_cast<int>(ni));
                if (joined < 0) { everyDaughter = false; break; }
                if (neighbour < 0) neighbour = joined;
            }
            if (!everyDaughter) continue;
            Diagnostic& w = g.diags.warning(node.span, "`" + node.name + "` is deleted by every daughter; write `" +
                                                           node.name + ";` to keep it");
            w.notes.push_back({r.nodes[static_cast<std::size_t>(neighbour)].span,
                               "deleting it also deletes every edge at it, such as its edge to `" +
                                   r.nodes[static_cast<std::size_t>(neighbour)].name + "`, which is kept"});
            w.notes.push_back({keeper->statement, "rule `" + p.rules[keeper->rule].name + "` keeps its `" +
                                                      p.kinds[static_cast<std::size_t>(node.kind)].name + "`"});
        }
    }
}

}  // namespace g2d::sema
