// The rule-wide checks and warnings, once the match and daughters are read.
#include "sema/rule_checker.hpp"

#include <cmath>
#include <algorithm>
#include <functional>
#include <set>

#include "g2d/style_store.hpp"
#include "sema/builtins.hpp"
#include "sema/const_fold.hpp"
#include "sema/decl_checker.hpp"
#include "sema/dpo_conditions.hpp"

#include "sema/graph_statements.hpp"

namespace g2d::sema {

using ir::ElemClass;
using ir::ElemRef;
using ir::Type;
using ir::TypeKind;

void RuleChecker::warnAnonymousEdgesDeleted(const ir::Daughter& dg) {
    if (d_.name.span.file != g_.mainFile) return;
    for (int e : dg.deletedEdges) {
        const auto& me = rule_.edges[e];
        if (!me.name.empty() || me.kind < 0 || me.src < 0 || me.dst < 0) continue;
        const bool srcKept = std::find(dg.deletedNodes.begin(), dg.deletedNodes.end(), me.src) == dg.deletedNodes.end();
        const bool dstKept = std::find(dg.deletedNodes.begin(), dg.deletedNodes.end(), me.dst) == dg.deletedNodes.end();
        if (!srcKept || !dstKept) continue;
        const bool directed = g_.prog.kinds[me.kind].directed;
        const std::string edge = rule_.nodes[me.src].name + " -[" + g_.prog.kinds[me.kind].name +
                                 (directed ? "]-> " : "]- ") + rule_.nodes[me.dst].name;
        Diagnostic d;
        d.span = me.span;
        d.message = "edge `" + edge + "` is deleted although both its nodes are kept (an edge without a name "
                    "cannot be kept); to keep it, name it (`e: " + edge + "`) and write `e;` in the daughter";
        d.notes.push_back({dg.span, "in this daughter"});
        pendingWarnings_.push_back(std::move(d));
    }
}

void RuleChecker::warnKeptFacesLosingCorners(const ir::Daughter& dg) {
    if (d_.name.span.file != g_.mainFile) return;
    for (const auto& kf : dg.keptFaces) {
        const auto& mf = rule_.faces[static_cast<std::size_t>(kf.motherFace)];
        for (int c : mf.corners) {
            if (std::find(dg.deletedNodes.begin(), dg.deletedNodes.end(), c) == dg.deletedNodes.end()) continue;
            const std::string corner = rule_.nodes[static_cast<std::size_t>(c)].name;
            Diagnostic d;
            d.span = kf.span;
            d.message = "face `" + mf.name + "` is kept but its corner `" + corner + "` is deleted, and the face with it; " +
                        "to keep the face, keep `" + corner + "` too (`" + corner + ";`)";
            d.notes.push_back({dg.span, "in this daughter"});
            pendingWarnings_.push_back(std::move(d));
            break;
        }
    }
}

void RuleChecker::checkAutoPlacement(const ir::Daughter& dg) {
    if (!dg.autoPlacement) return;
    for (const auto& mn : rule_.nodes) {
        if (mn.sketch || mn.anchorOf >= 0 || mn.kind < 0) continue;   // a wildcard without one takes no part
        auto& d = g_.diags.error(mn.span, "automatic placement needs a sketch position for every matched node but wildcards: "
                                          "give `" + mn.name + "` one with `@ (x, y)`");
        d.notes.push_back({dg.span, "a new node of this daughter is placed automatically"});
        return;
    }
}

void RuleChecker::checkOnlyAdds() {
    if (rule_.merge) {
        g_.diags.error(d_.name.span, "rule `" + rule_.name + "` cannot both `merge` and `intersect` (G^3 does one or the other per command)");
        return;
    }
    for (const auto& d : rule_.daughters) {
        std::string what;
        if (!d.deletedNodes.empty()) what = "deletes node `" + rule_.nodes[static_cast<std::size_t>(d.deletedNodes[0])].name + "`";
        else if (!d.deletedEdges.empty()) what = "deletes an edge of the match (to split an edge, keep it and rewire it: `s: m -[E]- b`)";
        else if (!d.deletedFaces.empty()) what = "deletes face `" + rule_.faces[static_cast<std::size_t>(d.deletedFaces[0])].name + "`";
        // Moves, radii, rewired edges, inserted corners and split faces are
        // undone by the graph's journal (graph_journal.hpp); attributes,
        // styles and deletions are not.
        for (const auto& n : d.nodes)
            if (what.empty() && n.motherNode >= 0 && (!n.assigns.empty() || !n.styles.empty()))
                what = "sets attributes or styles of node `" + n.name + "`";
        for (const auto& e : d.edges)
            if (what.empty() && e.motherEdge >= 0 && (!e.assigns.empty() || !e.styles.empty()))
                what = "sets attributes or styles of edge `" + e.name + "`";
        for (const auto& k : d.keptFaces)
            if (what.empty() && (!k.assigns.empty() || !k.styles.empty()))
                what = "sets attributes or styles of face `" + rule_.faces[static_cast<std::size_t>(k.motherFace)].name + "`";
        if (!what.empty()) {
            auto& diag = g_.diags.error(d.span, "a rule with `intersect` may add elements, move nodes, change radii, rewire "
                                                "its edges, `insert` and `split` (an application that would intersect the model is "
                                                "undone), but this daughter " + what);
            diag.notes.push_back({d_.name.span, "rule `" + rule_.name + "` has `intersect`"});
            return;
        }
        warnAlwaysIntersects(d);
    }
}

void RuleChecker::warnAlwaysIntersects(const ir::Daughter& d) {
    // A new edge from kept node k to a new node placed at `k.pos` has no
    // length: it lies on every other edge at k (the shared node's contact is
    // ignored, the rest of the new edge is that point), so the test refuses
    // every application while k keeps an edge of the match.
    if (d_.name.span.file != g_.mainFile) return;
    for (const auto& e : d.edges) {
        if (e.motherEdge >= 0 || e.src < 0 || e.dst < 0) continue;
        for (const auto& [keptEnd, newEnd] : {std::pair{e.src, e.dst}, std::pair{e.dst, e.src}}) {
            const auto& k = d.nodes[static_cast<std::size_t>(keptEnd)];
            const auto& n = d.nodes[static_cast<std::size_t>(newEnd)];
            if (k.motherNode < 0 || n.motherNode >= 0 || !n.position) continue;
            const ir::Expr& at = *n.position;
            const bool atK = at.op == ir::ExprOp::Fact && (at.fact == ir::ElemFact::Pos || at.fact == ir::ElemFact::Pos3) &&
                             at.elem.cls == ElemClass::Node && at.elem.index == k.motherNode;
            if (!atK) continue;
            for (std::size_t i = 0; i < rule_.edges.size(); ++i) {
                const auto& me = rule_.edges[i];
                if (me.src == me.dst || (me.src != k.motherNode && me.dst != k.motherNode)) continue;
                if (std::find(d.deletedEdges.begin(), d.deletedEdges.end(), static_cast<int>(i)) != d.deletedEdges.end()) continue;
                auto& diag = g_.diags.warning(n.span, "node `" + n.name + "` is placed at `" + k.name + ".pos`, so the new edge between them has "
                                                      "no length and lies on " + (me.name.empty() ? std::string("an edge of the match") : "edge `" + me.name + "`") +
                                                      " at `" + k.name + "`: rule `" + rule_.name + "`'s intersection test undoes every application");
                diag.notes.push_back({d_.name.span, "rule `" + rule_.name + "` has `intersect`"});
                return;
            }
        }
    }
}

void RuleChecker::warnUnusedLets() {
    for (const auto& l : locals_) finishedLocals_.push_back(l);
    for (const auto& l : finishedLocals_)
        if (!l.used && l.span.file == g_.mainFile && !d_.compoundMatch)
            g_.diags.warning(l.span, "`" + l.name + "` is never used");
    if (rule_.ordered)
        for (const auto& n : rule_.nodes)
            if (!n.sketch && n.anchorOf < 0) {
                g_.diags.error(n.span, "rule `" + rule_.name + "` is `ordered`: every matched node needs a sketch "
                                                              "position; give `" + n.name + "` one with `@ (x, y)`");
                break;
            }
    if (neverMatches_ && d_.name.span.file == g_.mainFile)
        g_.diags.warning(d_.name.span, d_.compoundMatch ? "compound `" + rule_.name + "` never has an instance: one of its conditions is always false"
                                                        : "rule `" + rule_.name + "` can never match: one of its conditions is always false");
}

}  // namespace g2d::sema
