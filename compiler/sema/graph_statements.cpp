#include "sema/graph_statements.hpp"

#include <cmath>
#include <algorithm>
#include <functional>
#include <set>

#include "g2d/style_store.hpp"
#include "sema/builtins.hpp"
#include "sema/const_fold.hpp"
#include "sema/decl_checker.hpp"
#include "sema/dpo_conditions.hpp"
#include "sema/element_facts.hpp"

#include "sema/graph_statements.hpp"

namespace g2d::sema {

using ir::ElemClass;
using ir::ElemRef;
using ir::Type;
using ir::TypeKind;

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
                      std::vector<ir::StyleAssign>& stylesOut, std::optional<ir::Expr>* radiusOut) {
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
        if (it == k.attrs.end() && radiusOut && a.name.name == "radius") {   // 2D: say which space has it
            g.diags.error(a.name.span, otherSpaceFact("radius", k.cls, g.prog.space3d));
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

bool ringOutsideDaughter(Globals& g, const ast::FaceStmt& f, const char* where) {
    if (!f.ring) return false;
    g.diags.error(f.ring->span, "`all " + f.ring->node.name + "` takes a node of every turn of a `for` loop: it makes a face in a "
                                    "daughter, after the loop, not in " + where);
    return true;
}

}  // namespace g2d::sema
