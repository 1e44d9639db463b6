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

#include "sema/daughter_checker.hpp"
#include "sema/graph_checker.hpp"
#include "sema/graph_statements.hpp"

namespace g2d::sema {

using ir::ElemClass;
using ir::ElemRef;
using ir::Type;
using ir::TypeKind;

void RuleChecker::run() {
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

void RuleChecker::options() {
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
                                                 suggest(o.word.name, {"priority", "pick", "ordered", "parallel", "merge", "intersect", "dpo", "weight", "limit"}));
            break;
        case ast::RuleOption::Kind::Pick:
            checkPick(o);
            break;
        case ast::RuleOption::Kind::Weight:
            ruleWeight(*o.weight);
            break;
        case ast::RuleOption::Kind::Limit:
            rule_.limit = checkStepLimit(g_, ec_, *o.limit);
            limitSpan_ = o.span;
            if (const auto n = rule_.limit ? fold(*rule_.limit, g_.prog) : std::nullopt; n && std::get<long long>(*n) == 0)
                g_.diags.warning(o.span, "rule `" + rule_.name + "` has `limit 0`: it never applies");
            break;
        }
    }
    // A generation applies all its rules in each step: one alone cannot stop.
    const auto prio = g_.prog.priorities.find(rule_.priority);
    if (rule_.limit && prio != g_.prog.priorities.end() && prio->second.generation)
        g_.diags.error(limitSpan_, "rule `" + rule_.name + "` is in `priority " + std::to_string(rule_.priority) +
                                       " generation`, whose steps apply all its rules at once: a rule of it cannot have a `limit` "
                                       "of its own (limit the priority instead)");
}

void RuleChecker::ruleWeight(const ast::Expr& e) {
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

void RuleChecker::checkPick(const ast::RuleOption& o) {
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

bool RuleChecker::isCornerlessFace(const ast::NodeStmt& n) const {
    if (!n.kind || n.wildcard) return false;
    const auto it = g_.kinds.find(n.kind->name);
    return it != g_.kinds.end() && g_.prog.kinds[it->second].cls == ElemClass::Face;
}

void RuleChecker::declarePatternNodes(const std::vector<ast::MatchStmt>& body, std::vector<ir::PatternNode>& out,
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

void RuleChecker::poison(const ast::Ident& name) {
    ElemBinding b;
    b.name = name.name;
    b.span = name.span;
    b.poisoned = true;
    bindings_.push_back(b);
}

bool RuleChecker::isPoisoned(const std::string& name) const {
    return std::any_of(bindings_.begin(), bindings_.end(),
                       [&](const ElemBinding& b) { return b.poisoned && b.name == name; });
}

std::optional<Span> RuleChecker::findName(const std::string& name) const {
    for (const auto& b : bindings_)
        if (b.name == name) return b.span;
    for (const auto& l : locals_)
        if (l.name == name) return l.span;
    return std::nullopt;
}

int RuleChecker::nodeIndex(const std::string& name) const {
    for (const auto& b : bindings_)
        if (b.name == name && b.ref.cls == ElemClass::Node && !b.poisoned) return b.ref.index;
    return -1;
}

void RuleChecker::declarePatternEdges(const std::vector<ast::MatchStmt>& body, std::vector<ir::PatternEdge>& out,
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

std::optional<ir::Condition> RuleChecker::condition(const ast::Expr& expr, const std::string& what) {
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

void RuleChecker::declarePatternFaces(const std::vector<ast::MatchStmt>& body, std::vector<ir::PatternFace>& faces,
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
        if (!f || ringOutsideDaughter(g_, *f, "a match")) continue;
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

void RuleChecker::patternConditions(const std::vector<ast::MatchStmt>& body, std::vector<ir::Condition>& out) {
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

void RuleChecker::match() {
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

bool RuleChecker::let(const ast::LetStmt& l, std::vector<ir::Let>& out, const std::vector<ElemBinding>& elems) {
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

void RuleChecker::items() {
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

void RuleChecker::weight(const ast::ProduceBlock& p, ir::Daughter& dg) {
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

std::string RuleChecker::fmtNumber(double x) {
    std::string s = std::to_string(x);
    while (s.size() > 1 && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

const ir::PatternEdge* RuleChecker::motherEdge(const std::string& name, int* index) const {
    for (std::size_t i = 0; i < rule_.edges.size(); ++i)
        if (!rule_.edges[i].name.empty() && rule_.edges[i].name == name) {
            if (index) *index = static_cast<int>(i);
            return &rule_.edges[i];
        }
    return nullptr;
}

int RuleChecker::motherFace(const std::string& name) const {
    for (std::size_t i = 0; i < rule_.faces.size(); ++i)
        if (rule_.faces[i].name == name) return static_cast<int>(i);
    return -1;
}

void RuleChecker::unboundName(const ast::Ident& id, const std::string& what) {
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

std::string RuleChecker::suggestElement(const std::string& name) {
    std::vector<std::string> candidates;
    for (const auto& b : bindings_) candidates.push_back(b.name);
    return suggest(name, candidates);
}


void RuleChecker::produce(const ast::ProduceBlock& p) { DaughterChecker(*this, p).run(); }

void checkRule(Globals& g, ExprChecker& ec, const ast::RuleDecl& d) { RuleChecker(g, ec, d).run(); }

}  // namespace g2d::sema
