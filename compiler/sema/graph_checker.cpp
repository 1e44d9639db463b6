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

namespace g2d::sema {

using ir::ElemClass;
using ir::ElemRef;
using ir::Type;
using ir::TypeKind;

namespace {

// Looks up a kind by name, requiring the given class; reports otherwise.
int resolveKind(Globals& g, const ast::Ident& name, ElemClass cls) {
    auto it = g.kinds.find(name.name);
    const std::string want = rt::elemClassName(cls);
    auto article = [](ElemClass c) { return std::string(c == ElemClass::Edge ? "an " : "a ") + rt::elemClassName(c); };
    if (it == g.kinds.end()) {
        std::vector<std::string> candidates;
        for (const auto& k : g.prog.kinds)
            if (k.cls == cls) candidates.push_back(k.name);
        g.diags.error(name.span, "unknown " + want + " kind `" + name.name + "`" + suggest(name.name, candidates));
        return -1;
    }
    if (const ElemClass is = g.prog.kinds[it->second].cls; is != cls) {
        g.diags.error(name.span, "`" + name.name + "` is " + article(is) + " kind, but " + article(cls) + " needs " +
                                     article(cls) + " kind");
        return -1;
    }
    return it->second;
}

// The arrow must agree with how the edge kind was declared.
bool checkArrow(Globals& g, const ast::EdgeStmt& e, int kind) {
    if (kind < 0) return false;
    const auto& k = g.prog.kinds[kind];
    const bool written = e.arrow != ast::EdgeStmt::Arrow::Undirected;
    if (written == k.directed) return true;
    if (k.directed)
        g.diags.error(e.kind.span, "edge kind `" + k.name + "` is directed: write `a -[" + k.name + "]-> b`");
    else
        g.diags.error(e.kind.span, "edge kind `" + k.name + "` is undirected: write `a -[" + k.name + "]- b`" +
                                       " (or declare it `edge " + k.name + " directed`)");
    return false;
}

bool usesPlaced(const ir::Expr& e) {
    if (e.op == ir::ExprOp::Placed) return true;
    return std::any_of(e.args.begin(), e.args.end(), [](const ir::Expr& a) { return usesPlaced(a); });
}

const ast::NodeStmt* asNode(const ast::GraphStmt& s) { return std::get_if<ast::NodeStmt>(&s.stmt); }
const ast::EdgeStmt* asEdge(const ast::GraphStmt& s) { return std::get_if<ast::EdgeStmt>(&s.stmt); }
const ast::FaceStmt* asFace(const ast::GraphStmt& s) { return std::get_if<ast::FaceStmt>(&s.stmt); }

// A face's corner, once: reports a name seen before in `seen` (a face's
// corners are distinct nodes) and returns false then.
bool firstTimeCorner(Globals& g, std::map<std::string, Span>& seen, const ast::Ident& c) {
    if (auto [prev, inserted] = seen.emplace(c.name, c.span); !inserted) {
        auto& d = g.diags.error(c.span, "corner `" + c.name + "` appears twice: a face's corners are distinct nodes");
        d.notes.push_back({prev->second, "first here"});
        return false;
    }
    return true;
}

void reportDuplicate(Globals& g, const ast::Ident& name, Span previous) {
    auto& d = g.diags.error(name.span, "`" + name.name + "` is already declared in this production");
    d.notes.push_back({previous, "previous declaration of `" + name.name + "` is here"});
}

// Checks `{ attr = expr, style.prop = expr }` against a kind.
void checkAssignments(Globals& g, ExprChecker& ec, int kind, const std::vector<ast::Assignment>& assigns,
                      const ExprEnv& env, std::vector<ir::AttrAssign>& attrsOut,
                      std::vector<ir::StyleAssign>& stylesOut, std::optional<ir::Expr>* radiusOut = nullptr) {
    std::set<std::string> seen;
    for (const auto& a : assigns) {
        const std::string key = (a.isStyle ? "style." : "") + a.name.name;
        if (!seen.insert(key).second) {
            g.diags.error(a.name.span, "`" + key + "` is assigned twice");
            continue;
        }
        if (a.isStyle) {
            auto v = ec.check(*a.value, env);
            if (!v) continue;
            checkStyleValue(g, a.name.name, *v);
            // Numbered for the runtime, which keeps a number in 16 bits.
            auto [known, added] = g.styleProps.emplace(a.name.name, static_cast<int>(g.prog.styleProps.size()));
            if (added) {
                if (g.prog.styleProps.size() >= rt::kMaxStyleProps) {
                    if (!g.tooManyStyleProps)
                        g.diags.error(a.name.span, "too many style properties: a program may set at most " +
                                                       std::to_string(rt::kMaxStyleProps) + " different ones");
                    g.tooManyStyleProps = true;
                    g.styleProps.erase(known);
                    continue;
                }
                g.prog.styleProps.push_back(a.name.name);
            }
            stylesOut.push_back(ir::StyleAssign{a.name.name, known->second, std::move(*v)});
            continue;
        }
        if (kind < 0) continue;
        const auto& k = g.prog.kinds[kind];
        if (a.name.name == "pos") {
            g.diags.error(a.name.span, "a node's position is set with `at`, not assigned");
            continue;
        }
        auto it = std::find_if(k.attrs.begin(), k.attrs.end(), [&](const auto& at) { return at.name == a.name.name; });
        // G^3's node radius (3D): a built-in field, unless the kind declares its own.
        if (it == k.attrs.end() && radiusOut && g.prog.space3d && a.name.name == "radius") {
            if (auto v = ec.checkAs(*a.value, ir::kFloatType, env, "the radius")) *radiusOut = std::move(*v);
            continue;
        }
        if (it == k.attrs.end()) {
            std::vector<std::string> candidates;
            for (const auto& at : k.attrs) candidates.push_back(at.name);
            g.diags.error(a.name.span, std::string(rt::elemClassName(k.cls)) + " kind `" + k.name +
                                           "` has no attribute `" + a.name.name + "`" + suggest(a.name.name, candidates));
            continue;
        }
        auto v = ec.checkAs(*a.value, it->type, env, "attribute `" + a.name.name + "`");
        if (!v) continue;
        attrsOut.push_back(ir::AttrAssign{static_cast<int>(it - k.attrs.begin()), std::move(*v)});
    }
}

std::optional<ir::Vec2> sketchOf(const ast::NodeStmt& n) {
    if (!n.sketch) return std::nullopt;
    return ir::Vec2{n.sketch->x, n.sketch->y};
}

}  // namespace

// ---- axiom -------------------------------------------------------------------

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
        if (!f) continue;
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

// ---- rules --------------------------------------------------------------------

namespace {

class RuleChecker {
public:
    RuleChecker(Globals& g, ExprChecker& ec, const ast::RuleDecl& d) : g_(g), ec_(ec), d_(d) {}

    void run() {
        const std::size_t errorsBefore = g_.diags.errorCount();
        rule_.name = d_.name.name;
        rule_.span = d_.span;
        options();
        match();
        items();
        warnUnusedLets();
        if (rule_.intersect) checkOnlyAdds();
        if (rule_.dpo) addDanglingConditions(rule_);
        // Advice about a rule is noise while the rule has errors.
        if (g_.diags.errorCount() == errorsBefore)
            for (auto& w : pendingWarnings_) g_.diags.warning(w.span, w.message).notes = w.notes;
        g_.prog.rules.push_back(std::move(rule_));
    }

private:
    void options() {
        std::set<std::pair<ast::RuleOption::Kind, std::string>> seen;
        for (const auto& o : d_.options) {
            if (!seen.insert({o.kind, o.word.name}).second) {
                g_.diags.error(o.span, "option given twice in rule `" + rule_.name + "`");
                continue;
            }
            switch (o.kind) {
            case ast::RuleOption::Kind::Priority:
                if (o.priorityOverflow) g_.diags.error(o.span, "priority is out of range (64-bit integers)");
                rule_.priority = o.priority;
                break;
            case ast::RuleOption::Kind::Ordered: rule_.ordered = true; break;
            case ast::RuleOption::Kind::Parallel: rule_.parallel = true; break;
            case ast::RuleOption::Kind::Word:
                if (o.word.name == "merge") rule_.merge = true;
                else if (o.word.name == "intersect") rule_.intersect = true;
                else if (o.word.name == "dpo") rule_.dpo = true;
                else g_.diags.error(o.word.span, "unknown rule option `" + o.word.name + "`" +
                                                     suggest(o.word.name, {"priority", "pick", "ordered", "parallel", "merge", "intersect", "dpo", "weight"}));
                break;
            case ast::RuleOption::Kind::Pick:
                checkPick(o);
                break;
            case ast::RuleOption::Kind::Weight:
                ruleWeight(*o.weight);
                break;
            }
        }
    }

    // `weight W`: a positive number of literals, constants and parameters.
    void ruleWeight(const ast::Expr& e) {
        ExprEnv env;
        env.context = "a rule's weight (it reads literals, constants and parameters)";
        env.allowRandom = false;
        env.allowElements = false;
        env.allowLocals = false;
        auto w = ec_.checkAs(e, ir::kFloatType, env, "a rule's weight");
        if (!w) return;
        std::string error;
        auto folded = fold(*w, g_.prog, &error);
        if (!error.empty()) {
            g_.diags.error(e.span, error + " in a rule's weight");
            return;
        }
        if (folded) {
            const double x = asNumber(*folded);
            if (!(x > 0) || !std::isfinite(x)) {
                g_.diags.error(e.span, "a rule's weight must be positive, but this is " + fmtNumber(x));
                return;
            }
            rule_.weight = x;
            return;
        }
        rule_.weightExpr = std::move(*w);
    }

    // `pick random`, `pick oldest`, `pick oldest age`, `pick oldest generation`.
    void checkPick(const ast::RuleOption& o) {
        const std::string& measure = o.pickMeasure.name;
        if (o.pick.name == "random") {
            rule_.pick = ir::Pick::Random;
            if (!measure.empty()) g_.diags.error(o.pickMeasure.span, "`pick random` takes no measure (`" + measure + "`)");
        } else if (o.pick.name == "oldest") {
            if (measure.empty() || measure == "age") {
                rule_.pick = ir::Pick::Oldest;
            } else if (measure == "generation") {
                rule_.pick = ir::Pick::OldestGeneration;
                g_.prog.tracksGenerations = true;
            } else {
                g_.diags.error(o.pickMeasure.span, "unknown measure `" + measure + "` for `pick oldest` (use `age` or `generation`)" +
                                                       suggest(measure, {"age", "generation"}));
            }
        } else {
            g_.diags.error(o.pick.span, "unknown match selection `" + o.pick.name + "` (use `random` or `oldest`)" +
                                            suggest(o.pick.name, {"random", "oldest"}));
        }
    }

    // `f: Kind;` in a match where Kind is a face kind: a face of any corner count.
    bool isCornerlessFace(const ast::NodeStmt& n) const {
        if (!n.kind || n.wildcard) return false;
        const auto it = g_.kinds.find(n.kind->name);
        return it != g_.kinds.end() && g_.prog.kinds[it->second].cls == ElemClass::Face;
    }

    // Declares pattern nodes (first pass) so edges may name nodes written later.
    void declarePatternNodes(const std::vector<ast::MatchStmt>& body, std::vector<ir::PatternNode>& out,
                             int indexBase, bool inNac) {
        for (const auto& m : body) {
            const auto* gs = std::get_if<ast::GraphStmt>(&m.stmt);
            if (!gs) continue;
            const auto* n = asNode(*gs);
            if (!n || isCornerlessFace(*n)) continue;
            if (auto prev = findName(n->name.name)) {
                reportDuplicate(g_, n->name, *prev);
                continue;
            }
            ir::PatternNode pn;
            pn.name = n->name.name;
            pn.span = n->span;
            pn.sketch = sketchOf(*n);
            if (n->wildcard) {
                pn.kind = -1;
            } else if (!n->kind) {
                g_.diags.error(n->name.span, std::string(inNac ? "a node of a negative condition" : "match node `" + n->name.name + "`") +
                                                 " needs a kind (`" + n->name.name + ": Kind`, or `" + n->name.name +
                                                 ": *` for a wildcard)");
                poison(n->name);
                continue;
            } else {
                pn.kind = resolveKind(g_, *n->kind, ElemClass::Node);
                if (pn.kind < 0) { poison(n->name); continue; }
            }
            if (n->position)
                g_.diags.error(n->position->span, "a match cannot place nodes (`at`); test positions with `where`");
            if (n->hasAssignBlock)
                g_.diags.error(n->span, "a match cannot assign attributes; test them with `where`");
            ElemBinding b;
            b.name = pn.name;
            b.ref = ElemRef{ElemClass::Node, indexBase + static_cast<int>(out.size())};
            b.kind = pn.kind;
            b.span = n->name.span;
            bindings_.push_back(b);
            out.push_back(std::move(pn));
        }
    }

    // Declares a name whose declaration failed, so that its uses stay silent.
    void poison(const ast::Ident& name) {
        ElemBinding b;
        b.name = name.name;
        b.span = name.span;
        b.poisoned = true;
        bindings_.push_back(b);
    }

    bool isPoisoned(const std::string& name) const {
        return std::any_of(bindings_.begin(), bindings_.end(),
                           [&](const ElemBinding& b) { return b.poisoned && b.name == name; });
    }

    std::optional<Span> findName(const std::string& name) const {
        for (const auto& b : bindings_)
            if (b.name == name) return b.span;
        for (const auto& l : locals_)
            if (l.name == name) return l.span;
        return std::nullopt;
    }

    int nodeIndex(const std::string& name) const {
        for (const auto& b : bindings_)
            if (b.name == name && b.ref.cls == ElemClass::Node && !b.poisoned) return b.ref.index;
        return -1;
    }

    void declarePatternEdges(const std::vector<ast::MatchStmt>& body, std::vector<ir::PatternEdge>& out,
                             int indexBase, const std::string& where) {
        for (const auto& m : body) {
            const auto* gs = std::get_if<ast::GraphStmt>(&m.stmt);
            if (!gs) continue;
            const auto* e = asEdge(*gs);
            if (!e) continue;
            ir::PatternEdge pe;
            pe.span = e->span;
            pe.kind = resolveKind(g_, e->kind, ElemClass::Edge);
            bool ok = checkArrow(g_, *e, pe.kind) && pe.kind >= 0;
            for (const auto* id : {&e->src, &e->dst}) {
                int idx = nodeIndex(id->name);
                if (idx < 0 && isPoisoned(id->name)) {
                    ok = false;
                } else if (idx < 0) {
                    bool isEdge = std::any_of(bindings_.begin(), bindings_.end(), [&](const ElemBinding& b) {
                        return b.name == id->name && b.ref.cls == ElemClass::Edge;
                    });
                    g_.diags.error(id->span, isEdge ? "edge endpoint `" + id->name + "` is an edge, not a node"
                                                    : "edge endpoint `" + id->name + "` is not a node of " + where);
                    ok = false;
                }
                (id == &e->src ? pe.src : pe.dst) = idx;
            }
            if (e->arrow == ast::EdgeStmt::Arrow::Backward) std::swap(pe.src, pe.dst);
            if (!e->assigns.empty())
                g_.diags.error(e->assigns.front().name.span, "a match cannot assign attributes; test them with `where`");
            if (e->name) {
                if (auto prev = findName(e->name->name)) {
                    reportDuplicate(g_, *e->name, *prev);
                    ok = false;
                } else {
                    pe.name = e->name->name;
                }
            }
            if (!ok) { pe.kind = -1; }
            const int index = indexBase + static_cast<int>(out.size());
            if (!pe.name.empty()) {
                ElemBinding b;
                b.name = pe.name;
                b.ref = ElemRef{ElemClass::Edge, index};
                b.kind = pe.kind;
                b.span = e->name->span;
                bindings_.push_back(b);
            }
            out.push_back(std::move(pe));
        }
    }

    std::optional<ir::Condition> condition(const ast::Expr& expr, const std::string& what) {
        ExprEnv env;
        env.context = "a match condition";
        env.allowRandom = false;
        env.allowLocals = false;
        env.elems = &bindings_;
        env.compoundValues = true;
        std::set<ElemRef> deps;
        env.deps = &deps;
        auto e = ec_.checkAs(expr, ir::kBoolType, env, what);
        if (!e) return std::nullopt;
        if (auto v = fold(*e, g_.prog); v && !std::get<bool>(*v)) neverMatches_ = true;
        return ir::Condition{std::move(*e), std::vector<ElemRef>(deps.begin(), deps.end())};
    }

    // A match's (or a negative condition's) faces, after its nodes and
    // edges: `f: Kind(a, b, c)` on its nodes, or `f: Kind` (any corner count,
    // bound through a hidden node at its first corner, appended to `nodes`;
    // see ir::PatternNode::anchorOf). Indices continue from faceBase and nodeBase.
    void declarePatternFaces(const std::vector<ast::MatchStmt>& body, std::vector<ir::PatternFace>& faces,
                             std::vector<ir::PatternNode>& nodes, int faceBase, int nodeBase, bool inNac) {
        for (const auto& m : body) {
            const auto* gs = std::get_if<ast::GraphStmt>(&m.stmt);
            const ast::FaceStmt* f = gs ? asFace(*gs) : nullptr;
            const ast::NodeStmt* n = gs ? asNode(*gs) : nullptr;
            ast::FaceStmt cornerless;   // `f: Kind;` read as a face
            if (!f && n && isCornerlessFace(*n)) {
                if (n->position || n->sketch || n->hasAssignBlock)
                    g_.diags.error(n->span, "a matched face takes no position, sketch or assignments; test it with `where`");
                cornerless.name = n->name;
                cornerless.kind = *n->kind;
                cornerless.span = n->span;
                f = &cornerless;
            }
            if (!f) continue;
            ir::PatternFace pf;
            pf.span = f->span;
            pf.kind = resolveKind(g_, f->kind, ElemClass::Face);
            if (!f->name && !inNac) {
                g_.diags.error(f->span, "name the matched face (`f: " + f->kind.name + "(…)`): a daughter keeps it by name "
                                        "(`f;`) or deletes it");
                continue;
            }
            if (f->name)
                if (auto prev = findName(f->name->name)) {
                    reportDuplicate(g_, *f->name, *prev);
                    continue;
                }
            if (f->name) pf.name = f->name->name;
            if (!f->assigns.empty())
                g_.diags.error(f->assigns.front().name.span, "a match cannot assign attributes; test them with `where`");
            if (!f->corners.empty() && f->corners.size() < 3)
                g_.diags.error(f->span, "a face needs at least 3 corners, got " + std::to_string(f->corners.size()));
            std::map<std::string, Span> seen;
            bool ok = pf.kind >= 0;
            for (const auto& c : f->corners) {
                if (!firstTimeCorner(g_, seen, c)) {
                    ok = false;
                    continue;
                }
                const int idx = nodeIndex(c.name);
                if (idx < 0) {
                    if (!isPoisoned(c.name))
                        g_.diags.error(c.span, "corner `" + c.name + "` is not a node of the match" +
                                                   (inNac ? " or this negative condition" : ""));
                    ok = false;
                }
                pf.corners.push_back(idx);
            }
            const int index = faceBase + static_cast<int>(faces.size());
            if (ok && pf.corners.empty()) {
                ir::PatternNode anchor;
                anchor.kind = -1;
                anchor.anchorOf = index;
                anchor.span = f->span;
                pf.anchor = nodeBase + static_cast<int>(nodes.size());
                nodes.push_back(std::move(anchor));
            }
            if (!ok) pf.kind = -1;
            if (f->name) {
                ElemBinding b;
                b.name = pf.name;
                b.ref = ElemRef{ElemClass::Face, index};
                b.kind = pf.kind;
                b.span = f->name->span;
                b.poisoned = !ok;
                bindings_.push_back(b);
            }
            faces.push_back(std::move(pf));
        }
    }

    // Per-element `where` clauses of a pattern, then stand-alone ones.
    void patternConditions(const std::vector<ast::MatchStmt>& body, std::vector<ir::Condition>& out) {
        for (const auto& m : body) {
            if (const auto* gs = std::get_if<ast::GraphStmt>(&m.stmt)) {
                const ast::Expr* w = asNode(*gs)   ? asNode(*gs)->where.get()
                                     : asEdge(*gs) ? asEdge(*gs)->where.get()
                                                   : asFace(*gs)->where.get();
                if (w)
                    if (auto c = condition(*w, "a `where` condition")) out.push_back(std::move(*c));
            } else if (const auto* ws = std::get_if<ast::WhereStmt>(&m.stmt)) {
                if (auto c = condition(*ws->cond, "a `where` condition")) out.push_back(std::move(*c));
            }
        }
    }

    void match() {
        declarePatternNodes(d_.match, rule_.nodes, 0, false);
        declarePatternEdges(d_.match, rule_.edges, 0, "the match");
        declarePatternFaces(d_.match, rule_.faces, rule_.nodes, 0, 0, false);
        if (rule_.ordered && !rule_.faces.empty())
            g_.diags.error(rule_.faces.front().span, "an `ordered` rule cannot match faces: a face's corners are bound in "
                                                     "cyclic order, whatever their positions");
        for (std::size_t i = 0; i < rule_.nodes.size(); ++i) {
            if (rule_.nodes[i].kind >= 0 || rule_.nodes[i].anchorOf >= 0) continue;
            const int node = static_cast<int>(i);
            const bool connected = std::any_of(rule_.edges.begin(), rule_.edges.end(), [&](const ir::PatternEdge& e) {
                return e.src == node || e.dst == node;
            }) || std::any_of(rule_.faces.begin(), rule_.faces.end(), [&](const ir::PatternFace& f) {
                return std::find(f.corners.begin(), f.corners.end(), node) != f.corners.end();
            });
            if (!connected)
                g_.diags.error(rule_.nodes[i].span, "wildcard node `" + rule_.nodes[i].name +
                                                        "` must be an endpoint of an edge or a corner of a face of the match");
        }
        patternConditions(d_.match, rule_.conditions);
        const std::size_t outerBindings = bindings_.size();
        for (const auto& m : d_.match) {
            const auto* nac = std::get_if<ast::NacBlock>(&m.stmt);
            if (!nac) continue;
            ir::NegativeCondition n;
            n.span = nac->span;
            n.outerNodes = static_cast<int>(rule_.nodes.size());
            n.outerEdges = static_cast<int>(rule_.edges.size());
            n.outerFaces = static_cast<int>(rule_.faces.size());
            for (const auto& inner : nac->body)
                if (const auto* nested = std::get_if<ast::NacBlock>(&inner.stmt))
                    g_.diags.error(nested->span, "negative conditions (`not { … }`) cannot be nested");
            if (nac->body.empty())
                g_.diags.error(nac->span, "empty negative condition: `not { }` would reject every match");
            declarePatternNodes(nac->body, n.nodes, n.outerNodes, true);
            declarePatternEdges(nac->body, n.edges, n.outerEdges, "the match or this negative condition");
            declarePatternFaces(nac->body, n.faces, n.nodes, n.outerFaces, n.outerNodes, true);
            patternConditions(nac->body, n.conditions);
            // NAC names are visible only inside the NAC.
            for (std::size_t i = outerBindings; i < bindings_.size(); ++i) nacNames_[bindings_[i].name] = bindings_[i].span;
            bindings_.resize(outerBindings);
            rule_.nacs.push_back(std::move(n));
        }
    }

    bool let(const ast::LetStmt& l, std::vector<ir::Let>& out, const std::vector<ElemBinding>& elems) {
        auto poisonLet = [&]() {
            locals_.push_back(LocalVar{l.name.name, Type::of(TypeKind::Void), -1, false, l.name.span, true});
            return false;
        };
        if (auto prev = findName(l.name.name)) {
            reportDuplicate(g_, l.name, *prev);
            return false;
        }
        for (const auto& b : elems)
            if (b.name == l.name.name) {
                reportDuplicate(g_, l.name, b.span);
                return false;
            }
        if (findBuiltin(l.name.name) || l.name.name == "pi" || l.name.name == "tau" || valueTypeNames().count(l.name.name)) {
            g_.diags.error(l.name.span, "`" + l.name.name + "` would hide the built-in `" + l.name.name + "`");
            return poisonLet();
        }
        ExprEnv env;
        env.context = "a let";
        env.locals = &locals_;
        env.elems = &elems;
        env.compoundValues = true;
        std::optional<ir::Expr> v;
        if (l.type) {
            auto t = resolveType(g_, *l.type);
            if (!t) return poisonLet();
            v = ec_.checkAs(*l.value, *t, env, "`" + l.name.name + "`");
        } else {
            v = ec_.check(*l.value, env);
        }
        if (!v) return poisonLet();  // declared but poisoned: its uses stay silent
        const int slot = rule_.localSlots++;
        locals_.push_back(LocalVar{l.name.name, v->type, slot, false, l.name.span, false});
        out.push_back(ir::Let{slot, l.name.name, std::move(*v)});
        return true;
    }

    void items() {
        bool anyProduce = false;
        for (const auto& item : d_.items) {
            if (const auto* l = std::get_if<ast::LetStmt>(&item.item)) {
                if (anyProduce)
                    g_.diags.error(l->span, "rule-level `let` must come before the `produce` blocks");
                let(*l, rule_.lets, bindings_);
                continue;
            }
            anyProduce = true;
            produce(std::get<ast::ProduceBlock>(item.item));
        }
        if (!anyProduce)
            g_.diags.error(d_.name.span, "rule `" + rule_.name + "` has no `produce` block (write `produce { }` to "
                                                                 "delete the whole match)");
    }

    void weight(const ast::ProduceBlock& p, ir::Daughter& dg) {
        if (!p.weight) { dg.weight = 1.0; return; }
        ExprEnv env;
        env.context = "a weight (weights read literals, constants, parameters and the matched elements)";
        env.allowRandom = false;
        env.allowLocals = false;
        env.locals = &locals_;
        env.elems = &bindings_;
        auto w = ec_.checkAs(*p.weight, ir::kFloatType, env, "a weight");
        if (!w) return;
        if (readsElements(*w)) {   // known per application only (ops.hpp: checkedMatchWeight)
            dg.weightReadsMatch = true;
            dg.weightExpr = std::move(*w);
            return;
        }
        std::string error;
        auto folded = fold(*w, g_.prog, &error);
        if (!error.empty()) {
            g_.diags.error(p.weight->span, error + " in a weight");
            return;
        }
        if (auto v = folded) {
            const double x = asNumber(*v);
            if (!(x > 0)) {
                g_.diags.error(p.weight->span, "a weight must be positive, but this is " + fmtNumber(x));
                return;
            }
            dg.weight = x;
        }
        dg.weightExpr = std::move(*w);
    }

    static std::string fmtNumber(double x) {
        std::string s = std::to_string(x);
        while (s.size() > 1 && s.back() == '0') s.pop_back();
        if (!s.empty() && s.back() == '.') s.pop_back();
        return s;
    }

    const ir::PatternEdge* motherEdge(const std::string& name, int* index) const {
        for (std::size_t i = 0; i < rule_.edges.size(); ++i)
            if (!rule_.edges[i].name.empty() && rule_.edges[i].name == name) {
                if (index) *index = static_cast<int>(i);
                return &rule_.edges[i];
            }
        return nullptr;
    }

    int motherFace(const std::string& name) const {
        for (std::size_t i = 0; i < rule_.faces.size(); ++i)
            if (rule_.faces[i].name == name) return static_cast<int>(i);
        return -1;
    }

    void unboundName(const ast::Ident& id, const std::string& what) {
        if (id.name.rfind("prev.", 0) == 0 || id.name.rfind("next.", 0) == 0) {
            g_.diags.error(id.span, "`" + id.name + "` names a node of a `for` loop's neighbouring turn: only inside `for`");
            return;
        }
        if (auto it = nacNames_.find(id.name); it != nacNames_.end()) {
            auto& d = g_.diags.error(id.span, "`" + id.name + "` belongs to a negative condition, which binds nothing "
                                                              "the daughter could use");
            d.notes.push_back({it->second, "declared here"});
            return;
        }
        for (const auto& l : locals_)
            if (l.name == id.name) {
                g_.diags.error(id.span, "`" + id.name + "` is a value (`let`), not " + what);
                return;
            }
        std::vector<std::string> candidates;
        for (const auto& b : bindings_) candidates.push_back(b.name);
        g_.diags.error(id.span, "unknown name `" + id.name + "`: it is not " + what + " of the match or this daughter" +
                                    suggest(id.name, candidates));
    }

    void produce(const ast::ProduceBlock& p) {
        ir::Daughter dg;
        dg.span = p.span;
        weight(p, dg);
        const std::size_t localsBefore = locals_.size();
        // Expressions in the daughter read the matched elements; new ones are not readable.
        std::vector<ElemBinding> elems = bindings_;
        std::map<int, int> keptNodes;       // mother node -> daughter node
        std::map<int, int> keptEdges;       // mother edge -> daughter edge
        std::map<std::string, Span> named;  // names used in this daughter
        std::map<std::string, int> newNodes;
        auto claim = [&](const ast::Ident& id) {
            if (auto [it, inserted] = named.emplace(id.name, id.span); !inserted) {
                auto& d = g_.diags.error(id.span, "`" + id.name + "` appears twice in this daughter");
                d.notes.push_back({it->second, "first appears here"});
                return false;
            }
            return true;
        };
        // Pass 1: lets (in order) and nodes (so edges can name nodes written later).
        struct PendingNode { const ast::NodeStmt* stmt; int index; };
        std::vector<PendingNode> pendingNodes;
        std::vector<std::pair<const ast::NodeStmt*, int>> keptEdgeStmts, keptFaceStmts;
        for (const auto& s : p.body) {
            if (!std::holds_alternative<ast::GraphStmt>(s.stmt)) continue;
            const auto* n = asNode(std::get<ast::GraphStmt>(s.stmt));
            if (!n) continue;
            if (n->where) g_.diags.error(n->where->span, "conditions (`where`) belong in the match");
            const int mother = nodeIndex(n->name.name);
            int motherEdgeIndex = -1;
            if (mother < 0 && motherEdge(n->name.name, &motherEdgeIndex)) {
                // `old;` or `old { … };` keeps a mother edge.
                if (!claim(n->name)) continue;
                if (n->kind || n->wildcard || n->sketch || n->position)
                    g_.diags.error(n->name.span, "`" + n->name.name + "` is an edge of the match; keep it with `" +
                                                     n->name.name + ";` or `" + n->name.name + " { … };`");
                keptEdgeStmts.push_back({n, motherEdgeIndex});
                continue;
            }
            if (const int face = mother < 0 ? motherFace(n->name.name) : -1; face >= 0) {
                // `f;` or `f { … };` keeps a mother face.
                if (!claim(n->name)) continue;
                if (n->kind || n->wildcard || n->sketch || n->position)
                    g_.diags.error(n->name.span, "`" + n->name.name + "` is a face of the match; keep it with `" +
                                                     n->name.name + ";` or `" + n->name.name + " { … };`");
                keptFaceStmts.push_back({n, face});
                continue;
            }
            if (!claim(n->name)) continue;
            if (mother < 0 && isPoisoned(n->name.name)) continue;
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
                keptNodes[mother] = static_cast<int>(dg.nodes.size());
            } else {
                if (n->wildcard) {
                    g_.diags.error(n->kindSpan, "`*` (wildcard) can only be used in a match");
                    continue;
                }
                if (!n->kind) {
                    if (nacNames_.count(n->name.name) || findName(n->name.name)) unboundName(n->name, "a node");
                    else
                        g_.diags.error(n->name.span, "unknown name `" + n->name.name + "`: a new node needs a kind (`" +
                                                         n->name.name + ": Kind`)" + suggestElement(n->name.name));
                    continue;
                }
                dn.kind = resolveKind(g_, *n->kind, ElemClass::Node);
                if (dn.kind < 0) continue;
                if (!n->position && !n->sketch && !g_.prog.angleLayout) {
                    g_.diags.error(n->name.span, "new node `" + dn.name + "` needs a position: `at EXPR`, or a sketch "
                                                                          "position `@ (x, y)` for automatic placement");
                }
                if (!n->position && n->sketch) dg.autoPlacement = true;
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
                newNodes[dn.name] = static_cast<int>(dg.nodes.size());
                elems.push_back(newNodeBinding(n->name, dn.kind, "this production", "the matched elements (their values before the step)"));
            }
            pendingNodes.push_back({n, static_cast<int>(dg.nodes.size())});
            dg.nodes.push_back(std::move(dn));
        }
        // Pass 2: lets, node attributes and positions, edges, in order.
        auto exprEnv = [&]() {
            ExprEnv env;
            env.context = "a daughter";
            env.locals = &locals_;
            env.elems = &elems;
            env.compoundValues = true;
            return env;
        };
        auto daughterNode = [&](const ast::Ident& id, const char* role = "edge endpoint") -> int {
            if (auto it = newNodes.find(id.name); it != newNodes.end()) return it->second;
            const int mother = nodeIndex(id.name);
            if (mother >= 0) {
                if (auto it = keptNodes.find(mother); it != keptNodes.end()) return it->second;
                // Naming a mother node as an endpoint keeps it.
                ir::DaughterNode dn;
                dn.name = id.name;
                dn.motherNode = mother;
                dn.kind = rule_.nodes[mother].kind;
                dn.sketch = rule_.nodes[mother].sketch;
                dn.span = id.span;
                keptNodes[mother] = static_cast<int>(dg.nodes.size());
                named.emplace(id.name, id.span);
                dg.nodes.push_back(std::move(dn));
                return keptNodes[mother];
            }
            int edgeIdx = -1;
            if (motherEdge(id.name, &edgeIdx) || motherFace(id.name) >= 0) {
                g_.diags.error(id.span, std::string(role) + " `" + id.name + "` is " +
                                            (edgeIdx >= 0 ? "an edge" : "a face") + ", not a node");
                return -1;
            }
            if (!isPoisoned(id.name)) unboundName(id, "a node");
            return -1;
        };
        std::size_t nodeCursor = 0;
        for (const auto& s : p.body) {
            if (const auto* l = std::get_if<ast::LetStmt>(&s.stmt)) {
                let(*l, dg.lets, elems);
                continue;
            }
            if (const auto* loop = std::get_if<ast::ForBlock>(&s.stmt)) {
                daughterLoop(*loop, dg, claim, daughterNode, exprEnv(), elems);
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
                else
                    dg.inserts.push_back(ir::Daughter::Insert{node, first, second, ins->span});
                continue;
            }
            if (const auto* sp = std::get_if<ast::SplitStmt>(&s.stmt)) {
                daughterSplit(*sp, dg, exprEnv(), elems);
                continue;
            }
            const auto& gs = std::get<ast::GraphStmt>(s.stmt);
            if (const auto* n = asNode(gs)) {
                if (nodeCursor < pendingNodes.size() && pendingNodes[nodeCursor].stmt == n) {
                    auto& dn = dg.nodes[pendingNodes[nodeCursor].index];
                    ++nodeCursor;
                    if (n->position) {
                        ExprEnv env = exprEnv();
                        if (dn.motherNode < 0 && dn.sketch) env.placedNode = pendingNodes[nodeCursor - 1].index;
                        auto pos = ec_.checkAs(*n->position, ir::positionType(g_.prog), env, "a position");
                        if (pos && usesPlaced(*pos)) dg.autoPlacement = true;
                        if (pos) dn.position = std::move(*pos);
                    }
                    if (dn.kind >= 0) checkAssignments(g_, ec_, dn.kind, n->assigns, exprEnv(), dn.assigns, dn.styles, &dn.radius);
                    continue;
                }
                for (const auto& [stmt, motherIndex] : keptEdgeStmts) {
                    if (stmt != n) continue;
                    const auto& me = rule_.edges[motherIndex];
                    ir::DaughterEdge de;
                    de.name = me.name;
                    de.motherEdge = motherIndex;
                    de.kind = me.kind;
                    de.span = n->span;
                    // Endpoints are resolved after the whole daughter (a later statement
                    // may name them); keeping an edge keeps its endpoints.
                    de.src = -3 - me.src;
                    de.dst = -3 - me.dst;
                    if (me.kind >= 0) checkAssignments(g_, ec_, me.kind, n->assigns, exprEnv(), de.assigns, de.styles);
                    keptEdges[motherIndex] = static_cast<int>(dg.edges.size());
                    dg.edges.push_back(std::move(de));
                }
                for (const auto& [stmt, motherIndex] : keptFaceStmts) {
                    if (stmt != n) continue;
                    ir::KeptFace kf;
                    kf.motherFace = motherIndex;
                    kf.span = n->span;
                    const int kind = rule_.faces[motherIndex].kind;
                    if (kind >= 0) checkAssignments(g_, ec_, kind, n->assigns, exprEnv(), kf.assigns, kf.styles);
                    dg.keptFaces.push_back(std::move(kf));
                }
                continue;
            }
            if (const auto* f = asFace(gs)) {
                daughterFace(*f, dg, claim, daughterNode, exprEnv());
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
                if (motherEdge(de.name, &mi)) {
                    de.motherEdge = mi;
                    const auto& me = rule_.edges[mi];
                    if (de.kind >= 0 && me.kind >= 0 && de.kind != me.kind) {
                        auto& d = g_.diags.error(e->kind.span, "kept edge `" + de.name + "` cannot change its kind from `" +
                                                                   g_.prog.kinds[me.kind].name + "` to `" +
                                                                   e->kind.name + "`");
                        d.notes.push_back({me.span, "matched here"});
                    }
                    keptEdges[mi] = static_cast<int>(dg.edges.size());
                } else if (nodeIndex(de.name) >= 0 || newNodes.count(de.name)) {
                    g_.diags.error(e->name->span, "`" + de.name + "` is a node, not an edge");
                    continue;
                } else if (nacNames_.count(de.name)) {
                    unboundName(*e->name, "an edge");
                    continue;
                }
            }
            de.src = daughterNode(e->src);
            de.dst = daughterNode(e->dst);
            if (e->arrow == ast::EdgeStmt::Arrow::Backward) std::swap(de.src, de.dst);
            if (de.kind >= 0) checkAssignments(g_, ec_, de.kind, e->assigns, exprEnv(), de.assigns, de.styles);
            dg.edges.push_back(std::move(de));
        }
        for (auto& de : dg.edges) {
            if (de.src <= -3) de.src = keepEndpointOf(-3 - de.src, dg, keptNodes, named);
            if (de.dst <= -3) de.dst = keepEndpointOf(-3 - de.dst, dg, keptNodes, named);
        }
        // A face that is split is kept until it is cut.
        for (const auto& sp : dg.splits)
            if (std::none_of(dg.keptFaces.begin(), dg.keptFaces.end(), [&](const ir::KeptFace& k) { return k.motherFace == sp.motherFace; }))
                dg.keptFaces.push_back(ir::KeptFace{sp.motherFace, {}, {}, sp.span});
        // Wildcards are always kept.
        for (std::size_t i = 0; i < rule_.nodes.size(); ++i)
            if (rule_.nodes[i].kind < 0 && !keptNodes.count(static_cast<int>(i)))
                keepEndpointOf(static_cast<int>(i), dg, keptNodes, named);
        for (std::size_t i = 0; i < rule_.nodes.size(); ++i)
            if (!keptNodes.count(static_cast<int>(i))) dg.deletedNodes.push_back(static_cast<int>(i));
        for (std::size_t i = 0; i < rule_.edges.size(); ++i)
            if (!keptEdges.count(static_cast<int>(i))) dg.deletedEdges.push_back(static_cast<int>(i));
        for (std::size_t i = 0; i < rule_.faces.size(); ++i)
            if (std::none_of(dg.keptFaces.begin(), dg.keptFaces.end(), [&](const ir::KeptFace& k) { return k.motherFace == static_cast<int>(i); }))
                dg.deletedFaces.push_back(static_cast<int>(i));
        checkAutoPlacement(dg);
        warnAnonymousEdgesDeleted(dg);
        warnKeptFacesLosingCorners(dg);
        // Daughter-level lets go out of scope; warn about unused ones now.
        for (std::size_t i = localsBefore; i < locals_.size(); ++i) finishedLocals_.push_back(locals_[i]);
        locals_.resize(localsBefore);
        rule_.daughters.push_back(std::move(dg));
    }

    // A face the daughter creates, on its nodes (kept or new), in order.
    template <class Claim, class DaughterNode>
    void daughterFace(const ast::FaceStmt& f, ir::Daughter& dg, Claim& claim, DaughterNode& daughterNode, const ExprEnv& env) {
        ir::NewFace df;
        df.span = f.span;
        df.kind = resolveKind(g_, f.kind, ElemClass::Face);
        if (f.where) g_.diags.error(f.where->span, "conditions (`where`) belong in the match");
        if (f.name) {
            if (!claim(*f.name)) return;
            int edgeIdx = -1;
            if (nodeIndex(f.name->name) >= 0 || motherEdge(f.name->name, &edgeIdx) || motherFace(f.name->name) >= 0) {
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
        dg.faces.push_back(std::move(df));
    }

    // A node the daughter (or a loop of it) creates: named, not readable.
    static ElemBinding newNodeBinding(const ast::Ident& name, int kind, const std::string& creator, const std::string& readable) {
        ElemBinding b;
        b.name = name.name;
        b.ref = ElemRef{ElemClass::Node, -1};
        b.kind = kind;
        b.span = name.span;
        b.unreadable = "`" + name.name + "` is created by " + creator + "; expressions can read only " + readable;
        return b;
    }

    // `for (u, v) in f.sides { … }` or `for c in f.corners { … }`: what each
    // turn creates, on the turn's corners, the daughter's nodes, its own new
    // nodes and the neighbouring turns' (`prev.m`, `next.m`).
    template <class Claim, class DaughterNode>
    void daughterLoop(const ast::ForBlock& fb, ir::Daughter& dg, Claim& claim, DaughterNode& daughterNode, ExprEnv env,
                      const std::vector<ElemBinding>& elems) {
        ir::FaceLoop loop;
        loop.span = fb.span;
        loop.motherFace = motherFace(fb.face.name);
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
        std::vector<ElemBinding> loopElems = elems;
        for (std::size_t i = 0; i < fb.vars.size(); ++i) {
            const auto& v = fb.vars[i];
            if (auto prev = findName(v.name)) {
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
            if (findName(n->name.name)) {
                reportDuplicate(g_, n->name, *findName(n->name.name));
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
        if (ok) dg.loops.push_back(std::move(loop));
    }

    // `split f [around Kind at POS {…}] with EdgeKind {…} [for c in f.corners
    // where COND];`: the corner `c` reads as a wildcard node, like a loop's.
    void daughterSplit(const ast::SplitStmt& sp, ir::Daughter& dg, ExprEnv env, const std::vector<ElemBinding>& elems) {
        ir::FaceSplit split;
        split.span = sp.span;
        split.motherFace = motherFace(sp.face.name);
        bool ok = true;
        if (split.motherFace < 0) {
            g_.diags.error(sp.face.span, "`" + sp.face.name + "` is not a face of the match: `split` cuts a matched face");
            ok = false;
        }
        for (const auto& other : dg.splits)
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
            std::vector<ElemBinding> cornerElems = elems;
            if (auto prev = findName(sp.var->name)) {
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
        if (ok) dg.splits.push_back(std::move(split));
    }

    std::string suggestElement(const std::string& name) {
        std::vector<std::string> candidates;
        for (const auto& b : bindings_) candidates.push_back(b.name);
        return suggest(name, candidates);
    }

    // The daughter node for a mother node, keeping it if it is not kept yet
    // (a kept edge keeps its endpoints; wildcards are always kept).
    int keepEndpointOf(int mother, ir::Daughter& dg, std::map<int, int>& keptNodes,
                       std::map<std::string, Span>& named) {
        if (mother < 0) return -1;
        if (auto it = keptNodes.find(mother); it != keptNodes.end()) return it->second;
        const auto& mn = rule_.nodes[mother];
        ir::DaughterNode dn;
        dn.name = mn.name;
        dn.motherNode = mother;
        dn.kind = mn.kind;
        dn.sketch = mn.sketch;
        dn.span = mn.span;
        keptNodes[mother] = static_cast<int>(dg.nodes.size());
        named.emplace(mn.name, mn.span);
        dg.nodes.push_back(std::move(dn));
        return keptNodes[mother];
    }

    // An anonymous match edge cannot be kept, so it is always deleted; when the
    // daughter keeps both its ends, that is most likely not what was meant.
    void warnAnonymousEdgesDeleted(const ir::Daughter& dg) {
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

    // A kept face whose corner the daughter deletes goes with that corner.
    void warnKeptFacesLosingCorners(const ir::Daughter& dg) {
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

    void checkAutoPlacement(const ir::Daughter& dg) {
        if (!dg.autoPlacement) return;
        for (const auto& mn : rule_.nodes) {
            if (mn.sketch || mn.anchorOf >= 0 || mn.kind < 0) continue;   // a wildcard without one takes no part
            auto& d = g_.diags.error(mn.span, "automatic placement needs a sketch position for every matched node but wildcards: "
                                              "give `" + mn.name + "` one with `@ (x, y)`");
            d.notes.push_back({dg.span, "a new node of this daughter is placed automatically"});
            return;
        }
    }

    // `intersect`: an application found to intersect is undone by removing
    // what it added, so it may only add (G^3's Create edge and Create face).
    void checkOnlyAdds() {
        if (rule_.merge) {
            g_.diags.error(d_.name.span, "rule `" + rule_.name + "` cannot both `merge` and `intersect` (G^3 does one or the other per command)");
            return;
        }
        for (const auto& d : rule_.daughters) {
            std::string what;
            if (!d.deletedNodes.empty()) what = "deletes node `" + rule_.nodes[static_cast<std::size_t>(d.deletedNodes[0])].name + "`";
            else if (!d.deletedEdges.empty()) what = "deletes an edge of the match";
            else if (!d.deletedFaces.empty()) what = "deletes face `" + rule_.faces[static_cast<std::size_t>(d.deletedFaces[0])].name + "`";
            else if (!d.inserts.empty()) what = "inserts a node into faces";
            else if (!d.splits.empty()) what = "splits a face";
            for (const auto& n : d.nodes)
                if (what.empty() && n.motherNode >= 0 && (n.position || n.radius || !n.assigns.empty() || !n.styles.empty()))
                    what = "changes node `" + n.name + "`";
            for (const auto& e : d.edges)
                if (what.empty() && e.motherEdge >= 0) {
                    const auto& me = rule_.edges[static_cast<std::size_t>(e.motherEdge)];
                    const bool rewired = d.nodes[static_cast<std::size_t>(e.src)].motherNode != me.src ||
                                         d.nodes[static_cast<std::size_t>(e.dst)].motherNode != me.dst;
                    if (rewired || !e.assigns.empty() || !e.styles.empty()) what = "changes edge `" + e.name + "`";
                }
            for (const auto& k : d.keptFaces)
                if (what.empty() && (!k.assigns.empty() || !k.styles.empty()))
                    what = "changes face `" + rule_.faces[static_cast<std::size_t>(k.motherFace)].name + "`";
            if (!what.empty()) {
                auto& diag = g_.diags.error(d.span, "a rule with `intersect` may only add elements (an application that would intersect "
                                                    "the model is undone), but this daughter " + what);
                diag.notes.push_back({d_.name.span, "rule `" + rule_.name + "` has `intersect`"});
                return;
            }
        }
    }

    void warnUnusedLets() {
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
            g_.diags.warning(d_.name.span, "rule `" + rule_.name + "` can never match: one of its conditions is always false");
    }

    Globals& g_;
    ExprChecker& ec_;
    const ast::RuleDecl& d_;
    ir::Rule rule_;
    std::vector<ElemBinding> bindings_;          // match elements
    std::map<std::string, Span> nacNames_;       // names declared inside negative conditions
    std::vector<LocalVar> locals_;               // lets in scope
    std::vector<LocalVar> finishedLocals_;       // lets out of scope, for the unused warning
    bool neverMatches_ = false;
    std::vector<Diagnostic> pendingWarnings_;    // emitted only if the rule has no errors
};

}  // namespace

void checkRule(Globals& g, ExprChecker& ec, const ast::RuleDecl& d) { RuleChecker(g, ec, d).run(); }

}  // namespace g2d::sema
