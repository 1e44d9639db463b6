#include "sema/lint.hpp"

#include "sema/deleted_node_lint.hpp"
#include "sema/mirrored_face_lint.hpp"

#include <algorithm>
#include <set>

namespace g2d::sema {

namespace {

// Whether applying daughter `d` of `r` leaves the graph exactly as it was:
// it keeps every matched element where and as it is, and makes nothing.
bool changesNothing(const ir::Rule& r, const ir::Daughter& d) {
    if (!d.deletedNodes.empty() || !d.deletedEdges.empty() || !d.deletedFaces.empty() || !d.faces.empty() || !d.loops.empty() ||
        !d.inserts.empty() || !d.splits.empty())
        return false;
    for (const auto& n : d.nodes)
        if (n.motherNode < 0 || n.position || n.radius || !n.assigns.empty() || !n.styles.empty()) return false;
    for (const auto& e : d.edges) {
        if (e.motherEdge < 0 || !e.assigns.empty() || !e.styles.empty()) return false;
        const auto& m = r.edges[static_cast<std::size_t>(e.motherEdge)];
        if (d.nodes[static_cast<std::size_t>(e.src)].motherNode != m.src || d.nodes[static_cast<std::size_t>(e.dst)].motherNode != m.dst)
            return false;
    }
    for (const auto& f : d.keptFaces)
        if (!f.assigns.empty() || !f.styles.empty()) return false;
    return true;
}

}  // namespace

void lintProgram(Globals& g) {
    const ir::Program& p = g.prog;
    // Kinds never change, so an element kind exists only if the axiom or some daughter creates it.
    std::set<int> created;
    for (const auto& n : p.axiom.nodes) created.insert(n.kind);
    for (const auto& e : p.axiom.edges) created.insert(e.kind);
    for (const auto& f : p.axiom.faces) created.insert(f.kind);
    for (const auto& r : p.rules)
        for (const auto& d : r.daughters) {
            for (const auto& n : d.nodes)
                if (n.motherNode < 0) created.insert(n.kind);
            for (const auto& e : d.edges)
                if (e.motherEdge < 0) created.insert(e.kind);
            for (const auto& f : d.faces) created.insert(f.kind);
            for (const auto& sp : d.splits) {
                if (sp.centre) created.insert(sp.centre->kind);
                created.insert(sp.edgeKind);
            }
            for (const auto& l : d.loops) {
                for (const auto& n : l.nodes) created.insert(n.kind);
                for (const auto& e : l.edges) created.insert(e.kind);
                for (const auto& f : l.faces) created.insert(f.kind);
            }
            for (const auto& f : d.ringFaces) created.insert(f.kind);
        }
    for (const auto& r : p.rules) {
        if (r.span.file != g.mainFile) continue;
        auto missing = [&](int kind) { return kind >= 0 && !created.count(kind); };
        std::string why;
        for (const auto& n : r.nodes)
            if (missing(n.kind)) { why = "node kind `" + p.kinds[n.kind].name + "`"; break; }
        if (why.empty())
            for (const auto& e : r.edges)
                if (missing(e.kind)) { why = "edge kind `" + p.kinds[e.kind].name + "`"; break; }
        if (why.empty())
            for (const auto& f : r.faces)
                if (missing(f.kind)) { why = "face kind `" + p.kinds[f.kind].name + "`"; break; }
        if (!why.empty())
            g.diags.warning(r.span, (r.compound >= 0 ? "compound `" + r.name + "` never has an instance" : "rule `" + r.name + "` can never match") +
                                        ": no element of " + why + " is ever created (the axiom has none and no rule makes one)");
    }
    for (const auto& r : p.rules)
        if (r.span.file == g.mainFile && r.compound < 0 && !r.daughters.empty() &&
            std::all_of(r.daughters.begin(), r.daughters.end(), [&](const ir::Daughter& d) { return changesNothing(r, d); }))
            g.diags.warning(r.span, "rule `" + r.name + "` changes nothing: it keeps its whole match as it is, so it can match at "
                                    "every step and only uses steps up");
    std::set<long long> used;
    for (const auto& r : p.rules) used.insert(r.priority);
    for (const auto& [prio, cfg] : p.priorities)
        if (!used.count(prio) && cfg.span.file == g.mainFile)
            g.diags.warning(cfg.span, "no rule has priority " + std::to_string(prio));
    for (std::size_t i = 0; i < p.params.size(); ++i)
        if (!g.paramUsed[i] && g.paramFile[i] == g.mainFile)
            g.diags.warning(p.params[i].span, "parameter `" + p.params[i].name + "` is never used");
    for (std::size_t i = 0; i < p.consts.size(); ++i)
        if (!g.constUsed[i] && g.constFile[i] == g.mainFile)
            g.diags.warning(p.consts[i].span, "constant `" + p.consts[i].name + "` is never used");
    warnForgottenNodes(g);
    warnMirroredFacePatterns(g);
}

}  // namespace g2d::sema
