#include "sema/daughter_checker.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdlib>

#include "sema/graph_statements.hpp"

namespace g2d::sema {

using ir::ElemClass;
using ir::ElemRef;

void DaughterChecker::run() {
    dg_.span = p_.span;
    r_.weight(p_, dg_);
    const std::size_t localsBefore = r_.locals_.size();
    // Expressions in the daughter read the matched elements; new ones are not readable.
    elems_ = r_.bindings_;
    declareNodes();
    statements();
    finish();
    // Daughter-level lets go out of scope; warn about unused ones now.
    for (std::size_t i = localsBefore; i < r_.locals_.size(); ++i) r_.finishedLocals_.push_back(r_.locals_[i]);
    r_.locals_.resize(localsBefore);
    rule_.daughters.push_back(std::move(dg_));
}

bool DaughterChecker::claim(const ast::Ident& id) {
    if (auto [it, inserted] = named_.emplace(id.name, id.span); !inserted) {
        auto& d = g_.diags.error(id.span, "`" + id.name + "` appears twice in this daughter");
        d.notes.push_back({it->second, "first appears here"});
        return false;
    }
    return true;
}

ExprEnv DaughterChecker::exprEnv() const {
    ExprEnv env;
    env.context = "a daughter";
    env.locals = &r_.locals_;
    env.elems = &elems_;
    env.compoundValues = true;
    return env;
}

int DaughterChecker::daughterNode(const ast::Ident& id, const char* role) {
    if (auto it = newNodes_.find(id.name); it != newNodes_.end()) return it->second;
    const int mother = r_.nodeIndex(id.name);
    if (mother >= 0) {
        if (auto it = keptNodes_.find(mother); it != keptNodes_.end()) return it->second;
        // Naming a mother node as an endpoint keeps it.
        ir::DaughterNode dn;
        dn.name = id.name;
        dn.motherNode = mother;
        dn.kind = rule_.nodes[mother].kind;
        dn.sketch = rule_.nodes[mother].sketch;
        dn.span = id.span;
        keptNodes_[mother] = static_cast<int>(dg_.nodes.size());
        named_.emplace(id.name, id.span);
        dg_.nodes.push_back(std::move(dn));
        return keptNodes_[mother];
    }
    int edgeIdx = -1;
    if (r_.motherEdge(id.name, &edgeIdx) || r_.motherFace(id.name) >= 0) {
        g_.diags.error(id.span, std::string(role) + " `" + id.name + "` is " +
                                    (edgeIdx >= 0 ? "an edge" : "a face") + ", not a node");
        return -1;
    }
    if (!r_.isPoisoned(id.name)) r_.unboundName(id, "a node");
    return -1;
}

// Pass 1: the nodes (so edges can name nodes written later), and which
// statements keep a matched edge or face.
void DaughterChecker::declareNodes() {
    for (const auto& s : p_.body) {
        if (!std::holds_alternative<ast::GraphStmt>(s.stmt)) continue;
        const auto* n = asNode(std::get<ast::GraphStmt>(s.stmt));
        if (!n) continue;
        if (n->where) g_.diags.error(n->where->span, "conditions (`where`) belong in the match");
        const int mother = r_.nodeIndex(n->name.name);
        int motherEdgeIndex = -1;
        if (mother < 0 && r_.motherEdge(n->name.name, &motherEdgeIndex)) {
            // `old;` or `old { … };` keeps a mother edge.
            if (!claim(n->name)) continue;
            if (n->kind || n->wildcard || n->sketch || n->position)
                g_.diags.error(n->name.span, "`" + n->name.name + "` is an edge of the match; keep it with `" +
                                                 n->name.name + ";` or `" + n->name.name + " { … };`");
            keptEdgeStmts_.push_back({n, motherEdgeIndex});
            continue;
        }
        if (const int face = mother < 0 ? r_.motherFace(n->name.name) : -1; face >= 0) {
            // `f;` or `f { … };` keeps a mother face.
            if (!claim(n->name)) continue;
            if (n->kind || n->wildcard || n->sketch || n->position)
                g_.diags.error(n->name.span, "`" + n->name.name + "` is a face of the match; keep it with `" +
                                                 n->name.name + ";` or `" + n->name.name + " { … };`");
            keptFaceStmts_.push_back({n, face});
            continue;
        }
        if (!claim(n->name)) continue;
        if (mother < 0 && r_.isPoisoned(n->name.name)) continue;
        ir::DaughterNode dn;
        dn.name = n->name.name;
        dn.span = n->span;
        dn.sketch = sketchOf(*n);
        if (mother >= 0) {
            const auto& mn = rule_.nodes[mother];
            dn.motherNode = mother;
            dn.kind = mn.kind;
            if (n->wildcard) {
                g_.diags.error(n->kindSpan, "`*` (wildcard) can only be used in a match");
            } else if (n->kind) {
                int k = resolveKind(g_, *n->kind, ElemClass::Node);
                if (k >= 0 && k != mn.kind) {
                    auto& d = g_.diags.error(n->kind->span, "kept node `" + dn.name + "` cannot change its kind from `" +
                                                               (mn.kind < 0 ? std::string("*") : g_.prog.kinds[mn.kind].name) +
                                                               "` to `" + n->kind->name + "`");
                    d.notes.push_back({mn.span, "matched here"});
                }
            }
            if (!dn.sketch) dn.sketch = mn.sketch;
            if (mn.kind < 0 && (n->position || n->hasAssignBlock))
                g_.diags.error(n->span, "wildcard node `" + dn.name + "` is left unchanged by the production; it "
                                                                      "cannot be moved or assigned");
            keptNodes_[mother] = static_cast<int>(dg_.nodes.size());
        } else {
            if (n->wildcard) {
                g_.diags.error(n->kindSpan, "`*` (wildcard) can only be used in a match");
                continue;
            }
            if (!n->kind) {
                if (r_.nacNames_.count(n->name.name) || r_.findName(n->name.name)) r_.unboundName(n->name, "a node");
                else
                    g_.diags.error(n->name.span, "unknown name `" + n->name.name + "`: a new node needs a kind (`" +
                                                     n->name.name + ": Kind`)" + r_.suggestElement(n->name.name));
                continue;
            }
            dn.kind = resolveKind(g_, *n->kind, ElemClass::Node);
            if (dn.kind < 0) continue;
            if (!n->position && !n->sketch && !g_.prog.angleLayout) {
                g_.diags.error(n->name.span, "new node `" + dn.name + "` needs a position: `at EXPR`, or a sketch "
                                                                      "position `@ (x, y)` for automatic placement");
            }
            if (!n->position && n->sketch) dg_.autoPlacement = true;
            if ((n->position || n->sketch) && g_.prog.angleLayout)
                g_.diags.error(n->name.span, "node `" + dn.name + "` is placed by the drawing step (`layout angles`): "
                                             "remove its `at` and `@`");
            if (!n->position && !n->sketch && g_.prog.angleLayout) {
                // Made at the origin; the drawing step places it before the step is committed.
                ir::Expr origin;
                origin.type = ir::positionType(g_.prog);
                origin.span = n->name.span;
                origin.value = ir::Vec2{0, 0};
                dn.position = std::move(origin);
            }
            newNodes_[dn.name] = static_cast<int>(dg_.nodes.size());
            elems_.push_back(newNodeBinding(n->name, dn.kind, "this production", "the matched elements (their values before the step)"));
        }
        pendingNodes_.push_back({n, static_cast<int>(dg_.nodes.size())});
        dg_.nodes.push_back(std::move(dn));
    }
}

// Pass 2: lets, node attributes and positions, edges, faces, loops, inserts
// and splits, in order.
void DaughterChecker::statements() {
    std::size_t nodeCursor = 0;
    for (const auto& s : p_.body) {
        if (const auto* l = std::get_if<ast::LetStmt>(&s.stmt)) {
            r_.let(*l, dg_.lets, elems_);
            continue;
        }
        if (const auto* loop = std::get_if<ast::ForBlock>(&s.stmt)) {
            daughterLoop(*loop, exprEnv());
            continue;
        }
        if (const auto* ins = std::get_if<ast::InsertStmt>(&s.stmt)) {
            const int node = daughterNode(ins->node, "inserted node");
            const int first = daughterNode(ins->first, "side end");
            const int second = daughterNode(ins->second, "side end");
            if (node < 0 || first < 0 || second < 0) continue;
            if (first == second)
                g_.diags.error(ins->second.span, "a side joins two different nodes, but both ends are `" + ins->first.name + "`");
            else if (node == first || node == second)
                g_.diags.error(ins->node.span, "`" + ins->node.name + "` is an end of the side it would be inserted into");
            else {
                dg_.inserts.push_back(ir::Daughter::Insert{node, first, second, ins->span});
                diagonalInsert(*ins, first, second);
            }
            continue;
        }
        if (const auto* sp = std::get_if<ast::SplitStmt>(&s.stmt)) {
            daughterSplit(*sp, exprEnv());
            continue;
        }
        const auto& gs = std::get<ast::GraphStmt>(s.stmt);
        if (const auto* n = asNode(gs)) {
            if (nodeCursor < pendingNodes_.size() && pendingNodes_[nodeCursor].stmt == n) {
                auto& dn = dg_.nodes[pendingNodes_[nodeCursor].index];
                ++nodeCursor;
                if (n->position) {
                    ExprEnv env = exprEnv();
                    if (dn.motherNode < 0 && dn.sketch) env.placedNode = pendingNodes_[nodeCursor - 1].index;
                    auto pos = ec_.checkAs(*n->position, ir::positionType(g_.prog), env, "a position");
                    if (pos && usesPlaced(*pos)) dg_.autoPlacement = true;
                    if (pos) dn.position = std::move(*pos);
                }
                if (dn.kind >= 0) checkAssignments(g_, ec_, dn.kind, n->assigns, exprEnv(), dn.assigns, dn.styles, &dn.radius);
                continue;
            }
            for (const auto& [stmt, motherIndex] : keptEdgeStmts_) {
                if (stmt != n) continue;
                const auto& me = rule_.edges[motherIndex];
                ir::DaughterEdge de;
                de.name = me.name;
                de.motherEdge = motherIndex;
                de.kind = me.kind;
                de.span = n->span;
                // Endpoints are resolved after the whole daughter (a later statement
                // may name them); keeping an edge keeps its endpoints.
                keptEdgeEnds_.push_back({dg_.edges.size(), me.src, me.dst});
                if (me.kind >= 0) checkAssignments(g_, ec_, me.kind, n->assigns, exprEnv(), de.assigns, de.styles);
                keptEdges_[motherIndex] = static_cast<int>(dg_.edges.size());
                dg_.edges.push_back(std::move(de));
            }
            for (const auto& [stmt, motherIndex] : keptFaceStmts_) {
                if (stmt != n) continue;
                ir::KeptFace kf;
                kf.motherFace = motherIndex;
                kf.span = n->span;
                const int kind = rule_.faces[motherIndex].kind;
                if (kind >= 0) checkAssignments(g_, ec_, kind, n->assigns, exprEnv(), kf.assigns, kf.styles);
                dg_.keptFaces.push_back(std::move(kf));
            }
            continue;
        }
        if (const auto* f = asFace(gs)) {
            if (f->ring) ringFaces_.push_back(f);
            else daughterFace(*f, exprEnv());
            continue;
        }
        const auto* e = asEdge(gs);
        ir::DaughterEdge de;
        de.span = e->span;
        de.kind = resolveKind(g_, e->kind, ElemClass::Edge);
        checkArrow(g_, *e, de.kind);
        if (e->where) g_.diags.error(e->where->span, "conditions (`where`) belong in the match");
        if (e->name) {
            if (!claim(*e->name)) continue;
            de.name = e->name->name;
            int mi = -1;
            if (r_.motherEdge(de.name, &mi)) {
                de.motherEdge = mi;
                const auto& me = rule_.edges[mi];
                if (de.kind >= 0 && me.kind >= 0 && de.kind != me.kind) {
                    auto& d = g_.diags.error(e->kind.span, "kept edge `" + de.name + "` cannot change its kind from `" +
                                                               g_.prog.kinds[me.kind].name + "` to `" +
                                                               e->kind.name + "`");
                    d.notes.push_back({me.span, "matched here"});
                }
                keptEdges_[mi] = static_cast<int>(dg_.edges.size());
            } else if (r_.nodeIndex(de.name) >= 0 || newNodes_.count(de.name)) {
                g_.diags.error(e->name->span, "`" + de.name + "` is a node, not an edge");
                continue;
            } else if (r_.nacNames_.count(de.name)) {
                r_.unboundName(*e->name, "an edge");
                continue;
            }
        }
        de.src = daughterNode(e->src);
        de.dst = daughterNode(e->dst);
        if (e->arrow == ast::EdgeStmt::Arrow::Backward) std::swap(de.src, de.dst);
        if (de.kind >= 0) checkAssignments(g_, ec_, de.kind, e->assigns, exprEnv(), de.assigns, de.styles);
        dg_.edges.push_back(std::move(de));
    }
    for (const auto* f : ringFaces_) ringFace(*f);
}

// What the daughter keeps and deletes of the match, once every statement is read.
void DaughterChecker::finish() {
    for (const KeptEdgeEnds& k : keptEdgeEnds_) {
        dg_.edges[k.edge].src = keepEndpointOf(k.motherSrc);
        dg_.edges[k.edge].dst = keepEndpointOf(k.motherDst);
    }
    // A face that is split is kept until it is cut.
    for (const auto& sp : dg_.splits)
        if (std::none_of(dg_.keptFaces.begin(), dg_.keptFaces.end(), [&](const ir::KeptFace& k) { return k.motherFace == sp.motherFace; }))
            dg_.keptFaces.push_back(ir::KeptFace{sp.motherFace, {}, {}, sp.span});
    // Wildcards are always kept.
    for (std::size_t i = 0; i < rule_.nodes.size(); ++i)
        if (rule_.nodes[i].kind < 0 && !keptNodes_.count(static_cast<int>(i)))
            keepEndpointOf(static_cast<int>(i));
    for (std::size_t i = 0; i < rule_.nodes.size(); ++i)
        if (!keptNodes_.count(static_cast<int>(i))) dg_.deletedNodes.push_back(static_cast<int>(i));
    for (std::size_t i = 0; i < rule_.edges.size(); ++i)
        if (!keptEdges_.count(static_cast<int>(i))) dg_.deletedEdges.push_back(static_cast<int>(i));
    for (std::size_t i = 0; i < rule_.faces.size(); ++i)
        if (std::none_of(dg_.keptFaces.begin(), dg_.keptFaces.end(), [&](const ir::KeptFace& k) { return k.motherFace == static_cast<int>(i); }))
            dg_.deletedFaces.push_back(static_cast<int>(i));
    r_.checkAutoPlacement(dg_);
    r_.warnAnonymousEdgesDeleted(dg_);
    r_.warnKeptFacesLosingCorners(dg_);
}


void DaughterChecker::daughterFace(const ast::FaceStmt& f, const ExprEnv& env) {
    ir::NewFace df;
    df.span = f.span;
    df.kind = resolveKind(g_, f.kind, ElemClass::Face);
    if (f.where) g_.diags.error(f.where->span, "conditions (`where`) belong in the match");
    if (f.name) {
        if (!claim(*f.name)) return;
        int edgeIdx = -1;
        if (r_.nodeIndex(f.name->name) >= 0 || r_.motherEdge(f.name->name, &edgeIdx) || r_.motherFace(f.name->name) >= 0) {
            g_.diags.error(f.name->span, "`" + f.name->name + "` is matched; a daughter's face needs a new name");
            return;
        }
        df.name = f.name->name;
    }
    if (f.corners.size() < 3)
        g_.diags.error(f.span, "a face needs at least 3 corners, got " + std::to_string(f.corners.size()));
    std::map<std::string, Span> seen;
    for (const auto& c : f.corners) {
        if (firstTimeCorner(g_, seen, c)) df.corners.push_back(daughterNode(c, "corner"));
    }
    if (df.kind >= 0) checkAssignments(g_, ec_, df.kind, f.assigns, env, df.assigns, df.styles);
    dg_.faces.push_back(std::move(df));
}

void DaughterChecker::ringFace(const ast::FaceStmt& f) {
    const ast::RingCorners& ring = *f.ring;
    ir::RingFace rf;
    rf.span = f.span;
    rf.kind = resolveKind(g_, f.kind, ElemClass::Face);
    bool ok = rf.kind >= 0;
    if (f.where) g_.diags.error(f.where->span, "conditions (`where`) belong in the match");
    if (f.name && !claim(*f.name)) ok = false;
    if (ring.every.name != "all") {
        g_.diags.error(ring.every.span, "a face's corners are nodes separated by commas, or `all " + ring.node.name +
                                            "` for node `" + ring.node.name + "` of every turn of a `for` loop");
        ok = false;
    }
    if (ring.order && ring.order->name != "reversed") {
        g_.diags.error(ring.order->span, "after `all " + ring.node.name + "` comes `reversed` or nothing, not `" + ring.order->name + "`");
        ok = false;
    }
    rf.reversed = ring.order.has_value();
    const auto it = loopNodes_.find(ring.node.name);
    if (it == loopNodes_.end()) {
        g_.diags.error(ring.node.span, "`all " + ring.node.name + "`: `" + ring.node.name +
                                           "` is no corner or new node of a `for` loop of this daughter (a face over all turns takes "
                                           "one node of each turn)");
        ok = false;
    } else if (it->second.first < 0) {
        ok = false;   // its loop had errors
    } else {
        rf.loop = it->second.first;
        rf.corner = it->second.second;
    }
    if (rf.kind >= 0) checkAssignments(g_, ec_, rf.kind, f.assigns, exprEnv(), rf.assigns, rf.styles);
    if (ok) dg_.ringFaces.push_back(std::move(rf));
}

ElemBinding DaughterChecker::newNodeBinding(const ast::Ident& name, int kind, const std::string& creator, const std::string& readable) {
    ElemBinding b;
    b.name = name.name;
    b.ref = ElemRef{ElemClass::Node, -1};
    b.kind = kind;
    b.span = name.span;
    b.unreadable = "`" + name.name + "` is created by " + creator + "; expressions can read only " + readable;
    return b;
}

void DaughterChecker::daughterLoop(const ast::ForBlock& fb, ExprEnv env) {
    ir::FaceLoop loop;
    loop.span = fb.span;
    loop.motherFace = r_.motherFace(fb.face.name);
    loop.sides = fb.vars.size() == 2;
    loop.firstVar = static_cast<int>(rule_.nodes.size());
    bool ok = true;
    if (loop.motherFace < 0) {
        g_.diags.error(fb.face.span, "`" + fb.face.name + "` is not a face of the match: a loop walks a matched face");
        ok = false;
    }
    const char* want = loop.sides ? "sides" : "corners";
    if (fb.what.name != want) {
        g_.diags.error(fb.what.span, fb.what.name == "sides" || fb.what.name == "corners"
                                         ? std::string(loop.sides ? "`for (u, v)` walks a face's sides: write `" + fb.face.name + ".sides`"
                                                                  : "`for c` walks a face's corners: write `" + fb.face.name + ".corners`")
                                         : "a loop walks `" + fb.face.name + ".sides` or `" + fb.face.name + ".corners`, not `" +
                                               fb.face.name + "." + fb.what.name + "`");
        ok = false;
    }
    std::vector<ElemBinding> loopElems = elems_;
    for (std::size_t i = 0; i < fb.vars.size(); ++i) {
        const auto& v = fb.vars[i];
        if (auto prev = r_.findName(v.name)) {
            reportDuplicate(g_, v, *prev);
            ok = false;
            continue;
        }
        if (!claim(v)) { ok = false; continue; }
        ElemBinding b;
        b.name = v.name;
        b.ref = ElemRef{ElemClass::Node, loop.firstVar + static_cast<int>(i)};
        b.kind = -1;   // a face's corners may be of any kind
        b.span = v.span;
        loopElems.push_back(b);
    }
    // Pass 1: the nodes each turn creates (so statements may name later ones).
    std::map<std::string, int> locals;
    std::vector<const ast::NodeStmt*> localStmts;
    for (const auto& st : fb.body) {
        if (const auto* l = std::get_if<ast::LetStmt>(&st.stmt)) {
            g_.diags.error(l->span, "a `let` inside `for` is not supported yet; compute the value in the loop's statements");
            ok = false;
            continue;
        }
        if (const auto* inner = std::get_if<ast::ForBlock>(&st.stmt)) {
            g_.diags.error(inner->span, "loops cannot be nested");
            ok = false;
            continue;
        }
        if (const auto* ins = std::get_if<ast::InsertStmt>(&st.stmt)) {
            g_.diags.error(ins->span, "`insert` inside `for` is not supported; insert outside the loop");
            ok = false;
            continue;
        }
        if (const auto* sp = std::get_if<ast::SplitStmt>(&st.stmt)) {
            g_.diags.error(sp->span, "`split` inside `for` is not supported; split outside the loop");
            ok = false;
            continue;
        }
        const auto* n = asNode(std::get<ast::GraphStmt>(st.stmt));
        if (!n) continue;
        if (!n->kind || n->wildcard) {
            g_.diags.error(n->span, "a loop creates elements (`m: Kind at …;`); keep or change matched ones outside it");
            ok = false;
            continue;
        }
        if (!claim(n->name)) { ok = false; continue; }
        if (r_.findName(n->name.name)) {
            reportDuplicate(g_, n->name, *r_.findName(n->name.name));
            ok = false;
            continue;
        }
        ir::LoopNode ln;
        ln.name = n->name.name;
        ln.span = n->span;
        ln.kind = resolveKind(g_, *n->kind, ElemClass::Node);
        if (!n->position) {
            g_.diags.error(n->name.span, "a node a loop creates needs a position: `at EXPR`");
            ok = false;
        }
        if (n->where) g_.diags.error(n->where->span, "conditions (`where`) belong in the match");
        locals[ln.name] = static_cast<int>(loop.nodes.size());
        loopElems.push_back(newNodeBinding(n->name, ln.kind, "this loop", "the matched elements and the loop's corners"));
        localStmts.push_back(n);
        loop.nodes.push_back(std::move(ln));
    }
    env.elems = &loopElems;
    auto ref = [&](const ast::Ident& id, const char* role) -> std::optional<ir::LoopNodeRef> {
        using Scope = ir::LoopNodeRef::Scope;
        for (std::size_t i = 0; i < fb.vars.size(); ++i)
            if (fb.vars[i].name == id.name) return ir::LoopNodeRef{Scope::Var, static_cast<int>(i)};
        if (auto it = locals.find(id.name); it != locals.end()) return ir::LoopNodeRef{Scope::Local, it->second};
        for (const auto& [prefix, scope] : {std::pair{"prev.", Scope::Prev}, std::pair{"next.", Scope::Next}})
            if (id.name.rfind(prefix, 0) == 0) {
                const std::string name = id.name.substr(5);
                if (auto it = locals.find(name); it != locals.end()) return ir::LoopNodeRef{scope, it->second};
                g_.diags.error(id.span, "`" + id.name + "`: `" + name + "` is not a node this loop creates");
                return std::nullopt;
            }
        const int d = daughterNode(id, role);
        if (d < 0) return std::nullopt;
        return ir::LoopNodeRef{Scope::Daughter, d};
    };
    // Pass 2: positions and attributes of the new nodes, then edges and faces, in order.
    for (std::size_t i = 0; i < localStmts.size(); ++i) {
        const auto* n = localStmts[i];
        auto& ln = loop.nodes[i];
        if (n->position)
            if (auto pos = ec_.checkAs(*n->position, ir::positionType(g_.prog), env, "a position")) ln.position = std::move(*pos);
        if (n->sketch) g_.diags.error(n->sketch->span, "a node a loop creates is placed with `at`, not a sketch position");
        if (ln.kind >= 0) checkAssignments(g_, ec_, ln.kind, n->assigns, env, ln.assigns, ln.styles, &ln.radius);
    }
    for (const auto& st : fb.body) {
        const auto* gs = std::get_if<ast::GraphStmt>(&st.stmt);
        if (!gs || asNode(*gs)) continue;
        if (const auto* e = asEdge(*gs)) {
            ir::LoopEdge le;
            le.span = e->span;
            le.kind = resolveKind(g_, e->kind, ElemClass::Edge);
            checkArrow(g_, *e, le.kind);
            if (e->name) g_.diags.error(e->name->span, "elements a loop creates cannot be named (but its nodes)");
            if (e->where) g_.diags.error(e->where->span, "conditions (`where`) belong in the match");
            auto src = ref(e->src, "edge endpoint"), dst = ref(e->dst, "edge endpoint");
            if (e->arrow == ast::EdgeStmt::Arrow::Backward) std::swap(src, dst);
            if (le.kind >= 0) checkAssignments(g_, ec_, le.kind, e->assigns, env, le.assigns, le.styles);
            if (!src || !dst) { ok = false; continue; }
            le.src = *src;
            le.dst = *dst;
            loop.edges.push_back(std::move(le));
        } else if (const auto* f = asFace(*gs)) {
            if (f->ring) {
                g_.diags.error(f->ring->span, "a face over all turns (`all " + f->ring->node.name +
                                                  "`) is made once: write it after the loop, not in it");
                ok = false;
                continue;
            }
            ir::LoopFace lf;
            lf.span = f->span;
            lf.kind = resolveKind(g_, f->kind, ElemClass::Face);
            if (f->name) g_.diags.error(f->name->span, "elements a loop creates cannot be named (but its nodes)");
            if (f->where) g_.diags.error(f->where->span, "conditions (`where`) belong in the match");
            if (f->corners.size() < 3)
                g_.diags.error(f->span, "a face needs at least 3 corners, got " + std::to_string(f->corners.size()));
            std::map<std::string, Span> seen;
            for (const auto& c : f->corners) {
                if (!firstTimeCorner(g_, seen, c)) {
                    ok = false;
                    continue;
                }
                if (auto r = ref(c, "corner")) lf.corners.push_back(*r);
                else ok = false;
            }
            if (lf.kind >= 0) checkAssignments(g_, ec_, lf.kind, f->assigns, env, lf.assigns, lf.styles);
            loop.faces.push_back(std::move(lf));
        }
    }
    const int index = ok ? static_cast<int>(dg_.loops.size()) : -1;
    for (std::size_t i = 0; i < fb.vars.size(); ++i)
        loopNodes_[fb.vars[i].name] = {index, ir::LoopNodeRef{ir::LoopNodeRef::Scope::Var, static_cast<int>(i)}};
    for (const auto& [name, i] : locals) loopNodes_[name] = {index, ir::LoopNodeRef{ir::LoopNodeRef::Scope::Local, i}};
    if (ok) dg_.loops.push_back(std::move(loop));
}

void DaughterChecker::daughterSplit(const ast::SplitStmt& sp, ExprEnv env) {
    ir::FaceSplit split;
    split.span = sp.span;
    split.motherFace = r_.motherFace(sp.face.name);
    bool ok = true;
    if (split.motherFace < 0) {
        g_.diags.error(sp.face.span, "`" + sp.face.name + "` is not a face of the match: `split` cuts a matched face");
        ok = false;
    }
    for (const auto& other : dg_.splits)
        if (ok && other.motherFace == split.motherFace) {
            auto& d = g_.diags.error(sp.face.span, "face `" + sp.face.name + "` is split twice in this daughter");
            d.notes.push_back({other.span, "first split here"});
            ok = false;
        }
    split.edgeKind = resolveKind(g_, sp.edgeKind, ElemClass::Edge);
    if (split.edgeKind < 0) ok = false;
    else checkAssignments(g_, ec_, split.edgeKind, sp.edgeAssigns, env, split.edgeAssigns, split.edgeStyles);
    if (sp.centre) {
        ir::LoopNode c;
        c.span = sp.centre->span;
        c.kind = resolveKind(g_, sp.centre->kind, ElemClass::Node);
        if (auto pos = ec_.checkAs(*sp.centre->position, ir::positionType(g_.prog), env, "a position")) c.position = std::move(*pos);
        else ok = false;
        if (c.kind < 0) ok = false;
        else checkAssignments(g_, ec_, c.kind, sp.centre->assigns, env, c.assigns, c.styles, &c.radius);
        split.centre = std::move(c);
    }
    if (sp.var) {
        split.firstVar = static_cast<int>(rule_.nodes.size());
        if (sp.loopFace.name != sp.face.name || sp.what.name != "corners") {
            g_.diags.error(sp.loopFace.span, "a split chooses among the corners of `" + sp.face.name + "`: write `for " + sp.var->name +
                                                 " in " + sp.face.name + ".corners where …`");
            ok = false;
        }
        std::vector<ElemBinding> cornerElems = elems_;
        if (auto prev = r_.findName(sp.var->name)) {
            reportDuplicate(g_, *sp.var, *prev);
            ok = false;
        }
        ElemBinding b;
        b.name = sp.var->name;
        b.ref = ElemRef{ElemClass::Node, split.firstVar};
        b.kind = -1;   // a face's corners may be of any kind
        b.span = sp.var->span;
        cornerElems.push_back(b);
        env.elems = &cornerElems;
        if (auto cond = ec_.checkAs(*sp.cond, ir::kBoolType, env, "a corner condition")) split.cond = std::move(*cond);
        else ok = false;
    }
    if (ok) dg_.splits.push_back(std::move(split));
}

int DaughterChecker::keepEndpointOf(int mother) {
    if (mother < 0) return -1;
    if (auto it = keptNodes_.find(mother); it != keptNodes_.end()) return it->second;
    const auto& mn = rule_.nodes[mother];
    ir::DaughterNode dn;
    dn.name = mn.name;
    dn.motherNode = mother;
    dn.kind = mn.kind;
    dn.sketch = mn.sketch;
    dn.span = mn.span;
    keptNodes_[mother] = static_cast<int>(dg_.nodes.size());
    named_.emplace(mn.name, mn.span);
    dg_.nodes.push_back(std::move(dn));
    return keptNodes_[mother];
}

void DaughterChecker::diagonalInsert(const ast::InsertStmt& ins, int first, int second) {
    const int a = dg_.nodes[static_cast<std::size_t>(first)].motherNode, b = dg_.nodes[static_cast<std::size_t>(second)].motherNode;
    if (a < 0 || b < 0) return;
    const ir::PatternFace* across = nullptr;
    for (const auto& f : rule_.faces) {
        const auto& c = f.corners;
        const auto ia = std::find(c.begin(), c.end(), a), ib = std::find(c.begin(), c.end(), b);
        if (ia == c.end() || ib == c.end()) continue;
        const auto gap = std::abs(ia - ib);
        if (gap == 1 || gap == static_cast<std::ptrdiff_t>(c.size()) - 1) return;   // a side of a matched face
        if (!across) across = &f;
    }
    if (across)
        g_.diags.warning(ins.span, "`" + ins.first.name + "` and `" + ins.second.name + "` are not neighbouring corners of face `" +
                                       across->name + "` (a diagonal), so this `insert` does not grow it: `" + ins.node.name +
                                       "` joins only faces with a side from `" + ins.first.name + "` to `" + ins.second.name + "`");
}

}  // namespace g2d::sema
