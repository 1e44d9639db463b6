#include "sema/graph_checker.hpp"

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

void checkAxiom(Globals& g, ExprChecker& ec, const ast::AxiomDecl& d) {
    ir::Axiom ax;
    ax.span = d.span;
    std::map<std::string, std::pair<int, Span>> nodes;  // name -> index
    std::map<std::string, Span> names;
    std::vector<ElemBinding> axiomNodes;
    for (const auto& s : d.body)
        if (const auto* n = asNode(s)) {
            ElemBinding b;
            b.name = n->name.name;
            b.span = n->name.span;
            b.unreadable = "axiom expressions cannot read other axiom nodes (`" + n->name.name +
                           "`); name shared positions with `const`";
            axiomNodes.push_back(b);
        }
    ExprEnv env;
    env.context = "the axiom";
    env.allowLocals = false;
    env.elems = &axiomNodes;
    for (const auto& s : d.body) {
        const auto* n = asNode(s);
        if (!n) continue;
        if (auto [it, inserted] = names.emplace(n->name.name, n->name.span); !inserted) {
            auto& diag = g.diags.error(n->name.span, "`" + n->name.name + "` is already declared in the axiom");
            diag.notes.push_back({it->second, "previous declaration is here"});
            continue;
        }
        ir::AxiomNode node;
        node.name = n->name.name;
        node.span = n->span;
        if (n->wildcard) {
            g.diags.error(n->kindSpan, "wildcard nodes (`*`) belong in a rule's match, not in the axiom");
        } else if (!n->kind) {
            g.diags.error(n->name.span, "axiom node `" + n->name.name + "` needs a kind: `" + n->name.name + ": Kind`");
        } else {
            node.kind = resolveKind(g, *n->kind, ElemClass::Node);
        }
        if (n->sketch) g.diags.error(n->sketch->span, "sketch positions (`@`) belong in rules; place axiom nodes with `at`");
        if (n->where) g.diags.error(n->where->span, "conditions (`where`) belong in a rule's match");
        if (n->position) {
            auto p = ec.checkAs(*n->position, ir::positionType(g.prog), env, "a position");
            if (p) node.position = std::move(*p);
        }
        if (node.kind >= 0) checkAssignments(g, ec, node.kind, n->assigns, env, node.assigns, node.styles, &node.radius);
        nodes[node.name] = {static_cast<int>(ax.nodes.size()), n->name.span};
        ax.nodes.push_back(std::move(node));
    }
    for (const auto& s : d.body) {
        const auto* e = asEdge(s);
        if (!e) continue;
        ir::AxiomEdge edge;
        edge.span = e->span;
        if (e->name) {
            edge.name = e->name->name;
            if (auto [it, inserted] = names.emplace(edge.name, e->name->span); !inserted) {
                auto& diag = g.diags.error(e->name->span, "`" + edge.name + "` is already declared in the axiom");
                diag.notes.push_back({it->second, "previous declaration is here"});
            }
        }
        edge.kind = resolveKind(g, e->kind, ElemClass::Edge);
        checkArrow(g, *e, edge.kind);
        if (e->where) g.diags.error(e->where->span, "conditions (`where`) belong in a rule's match");
        auto endpoint = [&](const ast::Ident& id) {
            auto it = nodes.find(id.name);
            if (it == nodes.end()) {
                g.diags.error(id.span, names.count(id.name) ? "edge endpoint `" + id.name + "` is an edge, not a node"
                                                            : "edge endpoint `" + id.name + "` is not a node of the axiom");
                return -1;
            }
            return it->second.first;
        };
        edge.src = endpoint(e->src);
        edge.dst = endpoint(e->dst);
        if (e->arrow == ast::EdgeStmt::Arrow::Backward) std::swap(edge.src, edge.dst);
        if (edge.kind >= 0) checkAssignments(g, ec, edge.kind, e->assigns, env, edge.assigns, edge.styles);
        ax.edges.push_back(std::move(edge));
    }
    for (const auto& s : d.body) {
        const auto* f = asFace(s);
        if (!f || ringOutsideDaughter(g, *f, "the axiom")) continue;
        ir::NewFace face;
        face.span = f->span;
        if (f->name) {
            face.name = f->name->name;
            if (auto [it, inserted] = names.emplace(face.name, f->name->span); !inserted) {
                auto& diag = g.diags.error(f->name->span, "`" + face.name + "` is already declared in the axiom");
                diag.notes.push_back({it->second, "previous declaration is here"});
            }
        }
        face.kind = resolveKind(g, f->kind, ElemClass::Face);
        if (f->where) g.diags.error(f->where->span, "conditions (`where`) belong in a rule's match");
        if (f->corners.size() < 3)
            g.diags.error(f->span, "a face needs at least 3 corners, got " + std::to_string(f->corners.size()));
        std::map<std::string, Span> seen;
        for (const auto& c : f->corners) {
            auto it = nodes.find(c.name);
            if (it == nodes.end()) {
                g.diags.error(c.span, names.count(c.name) ? "corner `" + c.name + "` is not a node"
                                                          : "corner `" + c.name + "` is not a node of the axiom");
                continue;
            }
            if (!firstTimeCorner(g, seen, c)) continue;
            face.corners.push_back(it->second.first);
        }
        if (face.kind >= 0) checkAssignments(g, ec, face.kind, f->assigns, env, face.assigns, face.styles);
        ax.faces.push_back(std::move(face));
    }
    g.prog.axiom = std::move(ax);
}

}  // namespace g2d::sema
