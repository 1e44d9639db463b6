#include "sema/expr_checker.hpp"

#include "g2d/drawing_cost.hpp"
#include "g2d/element_facts.hpp"

#include "sema/element_facts.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "sema/builtins.hpp"
#include "sema/const_fold.hpp"

namespace g2d::sema {

using ir::Expr;
using ir::ExprOp;
using ir::Type;
using ir::TypeKind;

namespace {


Expr literal(ir::Value v, Type t, Span s) {
    Expr e;
    e.op = ExprOp::Literal;
    e.type = t;
    e.value = std::move(v);
    e.span = s;
    return e;
}

}  // namespace

Expr ExprChecker::coerce(Expr e, Type to) {
    if (to.kind == TypeKind::Float && e.type.kind == TypeKind::Int) {
        if (e.op == ExprOp::Literal) {
            return literal(static_cast<double>(std::get<long long>(e.value)), ir::kFloatType, e.span);
        }
        Expr c;
        c.op = ExprOp::Call;
        c.builtin = ir::Builtin::ToFloat;
        c.type = ir::kFloatType;
        c.span = e.span;
        c.args.push_back(std::move(e));
        return c;
    }
    return e;
}

std::optional<Expr> ExprChecker::checkAs(const ast::Expr& e, Type expected, const ExprEnv& env,
                                         const std::string& what) {
    auto r = check(e, env);
    if (!r) return std::nullopt;
    if (r->type == expected) return r;
    if (expected.kind == TypeKind::Float && r->type.kind == TypeKind::Int) return coerce(std::move(*r), expected);
    // A position of the other space: say how the grammar says which it is in.
    std::string hint;
    if (expected == ir::positionType(g_.prog) && r->type.isVector())
        hint = g_.prog.space3d ? " (the grammar is declared `space 3d;`: write (x, y, z))"
                               : " (3D positions need `space 3d;` at the top of the grammar)";
    g_.diags.error(e.span, what + " must be " + tn(expected) + ", but this is " + tn(r->type) + hint);
    return std::nullopt;
}

std::optional<Expr> ExprChecker::check(const ast::Expr& e, const ExprEnv& env) {
    return std::visit(
        [&](const auto& n) -> std::optional<Expr> {
            using T = std::decay_t<decltype(n)>;
            if constexpr (std::is_same_v<T, ast::IntLit>) {
                if (n.overflow) {
                    g_.diags.error(e.span, "integer literal is out of range (at most 9223372036854775807)");
                    return std::nullopt;
                }
                return literal(n.value, ir::kIntType, e.span);
            } else if constexpr (std::is_same_v<T, ast::FloatLit>) {
                if (!std::isfinite(n.value)) {
                    g_.diags.error(e.span, "number literal is out of range");
                    return std::nullopt;
                }
                return literal(n.value, ir::kFloatType, e.span);
            } else if constexpr (std::is_same_v<T, ast::StringLit>) {
                return literal(n.value, ir::kStringType, e.span);
            } else if constexpr (std::is_same_v<T, ast::BoolLit>) {
                return literal(n.value, ir::kBoolType, e.span);
            } else if constexpr (std::is_same_v<T, ast::Name>) {
                return name(e, n, env);
            } else if constexpr (std::is_same_v<T, ast::Member>) {
                return member(e, n, env);
            } else if constexpr (std::is_same_v<T, ast::Call>) {
                return call(e, n, env);
            } else if constexpr (std::is_same_v<T, ast::VecLit>) {
                auto x = checkAs(*n.x, ir::kFloatType, env, "the x of a vector");
                auto y = checkAs(*n.y, ir::kFloatType, env, "the y of a vector");
                std::optional<Expr> z;
                if (n.z) z = checkAs(*n.z, ir::kFloatType, env, "the z of a vector");
                if (!x || !y || (n.z && !z)) return std::nullopt;
                Expr c;
                c.op = ExprOp::Call;
                c.builtin = n.z ? ir::Builtin::MakeVec3 : ir::Builtin::MakeVec2;
                c.type = n.z ? ir::kVec3Type : ir::kVec2Type;
                c.span = e.span;
                c.args.push_back(std::move(*x));
                c.args.push_back(std::move(*y));
                if (z) c.args.push_back(std::move(*z));
                return c;
            } else if constexpr (std::is_same_v<T, ast::Unary>) {
                return unary(e, n, env);
            } else if constexpr (std::is_same_v<T, ast::Binary>) {
                return binary(e, n, env);
            } else {
                return conditional(e, n, env);
            }
        },
        e.node);
}

// `count(K)`: the live elements of node or edge kind K, in a `layout angles` cost.
std::optional<Expr> ExprChecker::count(const ast::Expr& e, const ast::Call& c, const ExprEnv& env) {
    if (!env.counts) {
        g_.diags.error(c.callee.span, "`count(K)` is read only by the cost of `layout angles` (it cannot be used in " + env.context + ")");
        return std::nullopt;
    }
    const auto* kindName = c.args.size() == 1 ? std::get_if<ast::Name>(&c.args[0]->node) : nullptr;
    const auto kind = kindName ? g_.kinds.find(kindName->name) : g_.kinds.end();
    if (kind == g_.kinds.end() || g_.prog.kinds[static_cast<std::size_t>(kind->second)].cls == ir::ElemClass::Face) {
        g_.diags.error(c.args.size() == 1 ? c.args[0]->span : e.span, "`count` takes one node or edge kind, e.g. `count(Wall)`");
        return std::nullopt;
    }
    Expr r;
    r.op = ExprOp::Count;
    r.index = kind->second;
    r.type = ir::kIntType;
    r.span = e.span;
    return r;
}

std::optional<Expr> ExprChecker::name(const ast::Expr& e, const ast::Name& n, const ExprEnv& env) {
    const std::string& id = n.name;
    if (env.locals) {
        for (auto it = env.locals->rbegin(); it != env.locals->rend(); ++it) {
            if (it->name != id) continue;
            it->used = true;
            if (it->type.kind == TypeKind::Void) return std::nullopt;  // its own error was reported
            if (!env.allowLocals) {
                g_.diags.error(e.span, "`" + id + "` cannot be used in " + env.context);
                return std::nullopt;
            }
            Expr r;
            r.op = it->isFnArg ? ExprOp::FnArg : ExprOp::Local;
            r.index = it->slot;
            r.type = it->type;
            r.span = e.span;
            return r;
        }
    }
    if (env.counts && (id == "nodes" || id == "edges")) {
        Expr r;
        r.op = ExprOp::Count;
        r.index = id == "nodes" ? rt::KindCounts::kNodes : rt::KindCounts::kEdges;
        r.type = ir::kIntType;
        r.span = e.span;
        return r;
    }
    if (env.selfKind >= 0) {
        const auto& attrs = g_.prog.kinds[env.selfKind].attrs;
        for (std::size_t i = 0; i < attrs.size(); ++i) {
            if (attrs[i].name != id) continue;
            Expr r;
            r.op = ExprOp::SelfAttr;
            r.index = static_cast<int>(i);
            r.type = attrs[i].type;
            r.span = e.span;
            return r;
        }
    }
    if (env.selfKind >= 0) {
        if (const ElementFact* f = findElementFact(id, g_.prog.kinds[env.selfKind].cls, g_.prog.space3d)) {
            Expr r;
            r.op = ExprOp::SelfFact;
            r.fact = f->fact;
            if (rt::elementFactEntry(f->fact).reads & rt::kReadsGenerations) g_.prog.tracksGenerations = true;
            r.type = ir::Type::of(f->type);
            r.span = e.span;
            return r;
        }
        if (std::string other = otherSpaceFact(id, g_.prog.kinds[env.selfKind].cls, g_.prog.space3d); !other.empty()) {
            g_.diags.error(e.span, other);   // before `normal` is taken for the Gaussian
            return std::nullopt;
        }
    }
    if (env.elems) {
        for (const auto& b : *env.elems) {
            if (b.name != id) continue;
            if (b.poisoned) return std::nullopt;
            const char* what = b.ref.cls == ir::ElemClass::Node ? "a node" : b.ref.cls == ir::ElemClass::Edge ? "an edge" : "a face";
            g_.diags.error(e.span, "`" + id + "` is " + what + ", not a value; read one of its attributes" +
                                       (b.ref.cls == ir::ElemClass::Node ? " or `" + id + ".pos`" : "") +
                                       " instead");
            return std::nullopt;
        }
    }
    if (auto it = g_.params.find(id); it != g_.params.end()) {
        g_.paramUsed[it->second] = true;
        Expr r;
        r.op = ExprOp::Param;
        r.index = it->second;
        r.type = g_.prog.params[it->second].type;
        r.span = e.span;
        return r;
    }
    if (auto it = g_.consts.find(id); it != g_.consts.end()) {
        if (it->second >= g_.constsDeclared) {
            g_.diags.error(e.span, "constant `" + id + "` is used before its declaration");
            return std::nullopt;
        }
        g_.constUsed[it->second] = true;
        const auto& c = g_.prog.consts[it->second];
        if (c.type.kind == TypeKind::Void) return std::nullopt;  // its own error was reported
        Expr r;
        r.op = ExprOp::Const;
        r.index = it->second;
        r.type = c.type;
        r.span = e.span;
        return r;
    }
    if (auto it = g_.enumerators.find(id); it != g_.enumerators.end()) {
        if (it->second.size() > 1) {
            std::string which;
            for (const auto& v : it->second) which += (which.empty() ? "`" : ", `") + g_.prog.enums[v.enumId].name + "." + id + "`";
            g_.diags.error(e.span, "`" + id + "` is a value of several enums; write " + which);
            return std::nullopt;
        }
        return literal(it->second[0], Type::enumeration(it->second[0].enumId), e.span);
    }
    if (id == "placed") {
        if (env.placedNode < 0) {
            g_.diags.error(e.span, "`placed` (the automatic position) can only be used in `at` of a new node that has "
                                   "a sketch position `@ (x, y)`");
            return std::nullopt;
        }
        Expr r;
        r.op = ExprOp::Placed;
        r.index = env.placedNode;
        r.type = ir::positionType(g_.prog);
        r.span = e.span;
        return r;
    }
    if (id == "pi") return literal(std::numbers::pi, ir::kFloatType, e.span);
    if (id == "tau") return literal(2 * std::numbers::pi, ir::kFloatType, e.span);
    if (g_.kinds.count(id)) {
        g_.diags.error(e.span, "`" + id + "` is a kind, not a value");
        return std::nullopt;
    }
    if (g_.enums.count(id)) {
        g_.diags.error(e.span, "`" + id + "` is an enum type; write one of its values as `" + id + ".VALUE`");
        return std::nullopt;
    }
    if (g_.functions.count(id) || findBuiltin(id)) {
        g_.diags.error(e.span, "`" + id + "` is a function; call it with `" + id + "(…)`");
        return std::nullopt;
    }
    if (id == g_.definingConst) {
        g_.diags.error(e.span, "constant `" + id + "` is used in its own definition");
        return std::nullopt;
    }
    if (auto it = g_.laterValues.find(id); it != g_.laterValues.end()) {
        auto& d = g_.diags.error(e.span, "`" + id + "` is used before its declaration");
        d.notes.push_back({it->second, "`" + id + "` is declared here"});
        return std::nullopt;
    }
    std::vector<std::string> candidates = {"pi", "tau"};
    if (env.locals)
        for (const auto& l : *env.locals) candidates.push_back(l.name);
    if (env.selfKind >= 0)
        for (const auto& a : g_.prog.kinds[env.selfKind].attrs) candidates.push_back(a.name);
    if (env.elems)
        for (const auto& b : *env.elems) candidates.push_back(b.name);
    for (const auto& [k, v] : g_.params) candidates.push_back(k);
    for (const auto& [k, v] : g_.consts) candidates.push_back(k);
    for (const auto& [k, v] : g_.enumerators) candidates.push_back(k);
    g_.diags.error(e.span, "unknown name `" + id + "`" + suggest(id, candidates));
    return std::nullopt;
}

std::optional<Expr> ExprChecker::member(const ast::Expr& e, const ast::Member& m, const ExprEnv& env) {
    // `elem.attr`, `Enum.Value`: the object is a plain name that is not a local.
    if (const auto* objName = std::get_if<ast::Name>(&m.object->node)) {
        bool isLocal = false;
        if (env.locals)
            for (const auto& l : *env.locals) isLocal = isLocal || l.name == objName->name;
        if (!isLocal && env.elems) {
            for (const auto& b : *env.elems)
                if (b.name == objName->name) return elementMember(e, b, m.member, env);
        }
        if (!isLocal) {
            if (auto it = g_.compounds.find(objName->name); it != g_.compounds.end()) return compoundValue(e, it->second, m.member, env);
            if (auto it = g_.enums.find(objName->name); it != g_.enums.end()) {
                const auto& en = g_.prog.enums[it->second];
                for (std::size_t i = 0; i < en.values.size(); ++i)
                    if (en.values[i] == m.member.name)
                        return literal(ir::EnumValue{it->second, static_cast<int>(i)}, Type::enumeration(it->second),
                                       e.span);
                g_.diags.error(m.member.span, "enum `" + en.name + "` has no value `" + m.member.name + "`" +
                                                  suggest(m.member.name, en.values));
                return std::nullopt;
            }
        }
    }
    auto obj = check(*m.object, env);
    if (!obj) return std::nullopt;
    const bool isAxis = m.member.name == "x" || m.member.name == "y" || (obj->type.kind == TypeKind::Vec3 && m.member.name == "z");
    if (obj->type.isVector() && isAxis) {
        Expr r;
        r.op = m.member.name == "x" ? ExprOp::VecX : m.member.name == "y" ? ExprOp::VecY : ExprOp::VecZ;
        r.type = ir::kFloatType;
        r.span = e.span;
        r.args.push_back(std::move(*obj));
        return r;
    }
    if (obj->type.kind == TypeKind::Vec2)
        g_.diags.error(m.member.span, "a vec2 has only `.x` and `.y`, not `." + m.member.name + "`" +
                                          (m.member.name == "z" && !g_.prog.space3d ? " (positions have a z in grammars declared `space 3d;`)" : ""));
    else if (obj->type.kind == TypeKind::Vec3)
        g_.diags.error(m.member.span, "a vec3 has only `.x`, `.y` and `.z`, not `." + m.member.name + "`");
    else
        g_.diags.error(m.member.span, "a value of type " + tn(obj->type) + " has no member `." + m.member.name + "`");
    return std::nullopt;
}

// `C.name`: compound C's let, as the instance the rule runs in has it.
std::optional<Expr> ExprChecker::compoundValue(const ast::Expr& e, int compound, const ast::Ident& member, const ExprEnv& env) {
    const auto* name = std::get_if<ast::Name>(&std::get<ast::Member>(e.node).object->node);
    if (!env.compoundValues || compound < 0) {
        g_.diags.error(e.span, "`" + name->name + "." + member.name + "` is a compound's value: only the rules the compound runs can read it" +
                                   (env.compoundValues ? std::string(" (and compounds declared after it)") : ", not " + env.context));
        return std::nullopt;
    }
    const ir::Compound& c = g_.prog.compounds[static_cast<std::size_t>(compound)];
    std::vector<std::string> names;
    for (std::size_t i = 0; i < c.lets.size(); ++i) {
        if (c.lets[i].name != member.name) {
            names.push_back(c.lets[i].name);
            continue;
        }
        Expr r;
        r.op = ExprOp::CompoundValue;
        r.type = c.lets[i].type;
        r.span = e.span;
        r.index = compound;
        r.slot = static_cast<int>(i);
        g_.compoundReads[static_cast<int>(g_.prog.rules.size())].emplace(compound, e.span);
        return r;
    }
    g_.diags.error(member.span, "compound `" + c.name + "` has no `let " + member.name + "`" + suggest(member.name, names));
    return std::nullopt;
}

std::optional<Expr> ExprChecker::elementMember(const ast::Expr& e, const ElemBinding& b, const ast::Ident& member,
                                               const ExprEnv& env) {
    if (b.poisoned) return std::nullopt;
    if (!env.allowElements) {
        g_.diags.error(e.span, "`" + b.name + "` cannot be read in " + env.context);
        return std::nullopt;
    }
    if (!b.unreadable.empty()) {
        g_.diags.error(e.span, b.unreadable);
        return std::nullopt;
    }
    // A declared attribute first: it hides a fact of the same name (an edge
    // kind's own `length`, declared before edges had the fact).
    if (b.kind >= 0) {
        const auto& kind = g_.prog.kinds[b.kind];
        for (std::size_t i = 0; i < kind.attrs.size(); ++i) {
            if (kind.attrs[i].name != member.name) continue;
            Expr r;
            r.op = ExprOp::Attr;
            r.elem = b.ref;
            r.index = static_cast<int>(i);
            r.type = kind.attrs[i].type;
            r.span = e.span;
            if (env.deps) env.deps->insert(b.ref);
            return r;
        }
    }
    if (const ElementFact* f = findElementFact(member.name, b.ref.cls, g_.prog.space3d)) {
        Expr r;
        r.op = ExprOp::Fact;
        r.elem = b.ref;
        r.fact = f->fact;
        if (rt::elementFactEntry(f->fact).reads & rt::kReadsGenerations) g_.prog.tracksGenerations = true;
        r.type = ir::Type::of(f->type);
        r.span = e.span;
        if (env.deps) env.deps->insert(b.ref);
        return r;
    }
    if (std::string other = otherSpaceFact(member.name, b.ref.cls, g_.prog.space3d); !other.empty()) {
        g_.diags.error(member.span, other);
        return std::nullopt;
    }
    const bool isNode = b.ref.cls == ir::ElemClass::Node;
    if (b.kind < 0 && !isNode) return std::nullopt;   // an edge whose kind was unknown (reported already)
    if (b.kind < 0) {
        std::string facts;
        for (const auto& f : elementFacts())
            if (hasFact(f, ir::ElemClass::Node, g_.prog.space3d)) facts += (facts.empty() ? "" : ", ") + std::string(f.name);
        g_.diags.error(member.span, "wildcard node `" + b.name + "` matches any kind, so it has no attribute `" +
                                        member.name + "`; only " + facts + " can be read");
        return std::nullopt;
    }
    const auto& kind = g_.prog.kinds[b.kind];
    std::vector<std::string> candidates;
    for (const auto& a : kind.attrs) candidates.push_back(a.name);
    for (const auto& f : elementFacts())
        if (hasFact(f, b.ref.cls, g_.prog.space3d)) candidates.push_back(f.name);
    std::string hint = suggest(member.name, candidates);
    if (hint.empty() && !kind.attrs.empty()) {   // no close name: list what there is
        hint = "; its attributes: ";
        for (std::size_t i = 0; i < kind.attrs.size(); ++i) hint += (i ? ", " : "") + kind.attrs[i].name;
    }
    g_.diags.error(member.span, std::string(rt::elemClassName(b.ref.cls)) + " kind `" + kind.name +
                                    "` has no attribute `" + member.name + "`" + hint);
    return std::nullopt;
}

bool ExprChecker::checkFormatTemplate(const ast::Expr& templ, std::size_t valueCount) {
    const auto* lit = std::get_if<ast::StringLit>(&templ.node);
    if (!lit) {
        g_.diags.error(templ.span, "the template of `format` must be a string literal");
        return false;
    }
    const std::string& s = lit->value;
    std::size_t holes = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '{' && i + 1 < s.size() && s[i + 1] == '{') { ++i; continue; }
        if (s[i] == '}' && i + 1 < s.size() && s[i + 1] == '}') { ++i; continue; }
        if (s[i] == '}') {
            g_.diags.error(templ.span, "unmatched `}` in format template (write `}}` for a literal brace)");
            return false;
        }
        if (s[i] != '{') continue;
        std::size_t close = s.find('}', i);
        if (close == std::string::npos) {
            g_.diags.error(templ.span, "unclosed `{` in format template (write `{{` for a literal brace)");
            return false;
        }
        std::string spec = s.substr(i + 1, close - i - 1);
        // Accepted: `{}` and `{:.N}` (N decimals, 0..17).
        bool ok = spec.empty();
        if (!ok && spec.size() >= 3 && spec[0] == ':' && spec[1] == '.' &&
            std::all_of(spec.begin() + 2, spec.end(), [](char c) { return c >= '0' && c <= '9'; }) &&
            spec.size() <= 4)
            ok = std::stoi(spec.substr(2)) <= 17;
        if (!ok) {
            g_.diags.error(templ.span, "unsupported placeholder `{" + spec + "}` in format template (use `{}` or `{:.N}`)");
            return false;
        }
        ++holes;
        i = close;
    }
    if (holes != valueCount) {
        g_.diags.error(templ.span, "format template has " + std::to_string(holes) + " placeholder" +
                                       (holes == 1 ? "" : "s") + " but " + std::to_string(valueCount) + " value" +
                                       (valueCount == 1 ? " is" : "s are") + " given");
        return false;
    }
    return true;
}

std::optional<Expr> ExprChecker::call(const ast::Expr& e, const ast::Call& c, const ExprEnv& env) {
    const std::string& fname = c.callee.name;
    if (fname == "count" && !g_.functions.count(fname)) return count(e, c, env);
    std::vector<Expr> args;
    bool ok = true;
    for (const auto& a : c.args) {
        auto r = check(*a, env);
        if (r) args.push_back(std::move(*r));
        else ok = false;
    }
    if (auto it = g_.functions.find(fname); it != g_.functions.end()) {
        if (it->second >= g_.functionsDeclared) {
            g_.diags.error(c.callee.span, it->second == g_.functionsDeclared
                                              ? "function `" + fname + "` cannot call itself (no recursion)"
                                              : "function `" + fname + "` is used before its declaration");
            return std::nullopt;
        }
        if (!ok) return std::nullopt;
        const auto& fn = g_.prog.functions[it->second];
        if (!env.allowRandom && usesRandom(fn.body, g_.prog)) {
            g_.diags.error(c.callee.span, "function `" + fname + "` draws random numbers, which cannot be used in " +
                                              env.context);
            return std::nullopt;
        }
        if (args.size() != fn.paramTypes.size()) {
            g_.diags.error(e.span, "`" + fname + "` takes " + std::to_string(fn.paramTypes.size()) + " argument" +
                                       (fn.paramTypes.size() == 1 ? "" : "s") + ", got " + std::to_string(args.size()));
            return std::nullopt;
        }
        Expr r;
        r.op = ExprOp::CallFn;
        r.index = it->second;
        r.type = fn.result;
        r.span = e.span;
        for (std::size_t i = 0; i < args.size(); ++i) {
            const Type want = fn.paramTypes[i];
            if (!(args[i].type == want) && !(want.kind == TypeKind::Float && args[i].type.kind == TypeKind::Int)) {
                g_.diags.error(c.args[i]->span, "argument " + std::to_string(i + 1) + " of `" + fname + "` (`" +
                                                    fn.paramNames[i] + "`) must be " + tn(want) + ", got " +
                                                    tn(args[i].type));
                return std::nullopt;
            }
            r.args.push_back(coerce(std::move(args[i]), want));
        }
        return r;
    }
    const BuiltinInfo* info = findBuiltin(fname);
    if (auto later = g_.laterFunctions.find(fname); !info && later != g_.laterFunctions.end()) {
        auto& d = g_.diags.error(c.callee.span, "function `" + fname + "` is used before its declaration");
        d.notes.push_back({later->second, "`" + fname + "` is declared here"});
        return std::nullopt;
    }
    if (!info) {
        std::vector<std::string> candidates;
        for (const auto& b : builtinFunctions()) candidates.push_back(b.name);
        for (const auto& [k, v] : g_.functions) candidates.push_back(k);
        std::string hint = suggest(fname, candidates);
        // Other languages' names for g2d's built-ins.
        static const std::map<std::string, std::string> aliases = {
            {"norm", "length"}, {"len", "length"}, {"magnitude", "length"}, {"mag", "length"}, {"abs_vec", "length"},
            {"normalise", "normalize"}, {"unit", "normalize"}, {"mix", "lerp"}, {"dist", "distance"},
            {"rand", "random"}, {"randrange", "randint"}, {"gauss", "normal"}, {"arctan", "atan"},
            {"toint", "int"}, {"tofloat", "float"}, {"to_string", "str"}};
        if (hint.empty())
            if (auto a = aliases.find(fname); a != aliases.end() && findBuiltin(a->second)) hint = "; g2d calls it `" + a->second + "`";
        g_.diags.error(c.callee.span, "unknown function `" + fname + "`" + hint);
        return std::nullopt;
    }
    if (drawsRandom(*info) && !env.allowRandom) {
        // A condition must give the same answer whenever it is asked.
        const bool condition = env.context == "a match condition";
        g_.diags.error(c.callee.span, "random function `" + fname + "` cannot be used in " + env.context +
                                          (condition ? "; draw the value when the element is created, into an attribute "
                                                       "(`n: K { r = " + fname + "(…) }` in the daughter that makes it), "
                                                       "and test the attribute"
                                                     : ""));
        return std::nullopt;
    }
    if (!ok) return std::nullopt;
    std::vector<Type> types;
    for (const auto& a : args) types.push_back(a.type);
    auto res = resolveBuiltin(fname, types, g_.prog);
    if (auto* err = std::get_if<BuiltinError>(&res)) {
        Span at = err->argument >= 0 && static_cast<std::size_t>(err->argument) < c.args.size()
                      ? c.args[err->argument]->span : e.span;
        g_.diags.error(at, err->message);
        return std::nullopt;
    }
    auto& resolved = std::get<BuiltinResolution>(res);
    if (resolved.builtin == ir::Builtin::Format && !checkFormatTemplate(*c.args[0], args.size() - 1))
        return std::nullopt;
    Expr r;
    r.op = ExprOp::Call;
    r.builtin = resolved.builtin;
    r.type = resolved.result;
    r.span = e.span;
    for (std::size_t i = 0; i < args.size(); ++i) r.args.push_back(coerce(std::move(args[i]), resolved.paramTypes[i]));
    return r;
}

std::optional<Expr> ExprChecker::unary(const ast::Expr& e, const ast::Unary& u, const ExprEnv& env) {
    auto operand = check(*u.operand, env);
    if (!operand) return std::nullopt;
    if (u.op == ast::UnaryOp::Not) {
        if (operand->type.kind != TypeKind::Bool) {
            g_.diags.error(e.span, "`not` needs a bool, but this is " + tn(operand->type));
            return std::nullopt;
        }
    } else if (!operand->type.isNumeric() && !operand->type.isVector()) {
        g_.diags.error(e.span, std::string("unary `") + (u.op == ast::UnaryOp::Neg ? "-" : "+") +
                                   "` needs a number or a vector, but this is " + tn(operand->type));
        return std::nullopt;
    }
    if (u.op == ast::UnaryOp::Plus) return operand;
    Expr r;
    r.op = u.op == ast::UnaryOp::Neg ? ExprOp::Neg : ExprOp::Not;
    r.type = operand->type;
    r.span = e.span;
    r.args.push_back(std::move(*operand));
    return r;
}

std::optional<Expr> ExprChecker::binary(const ast::Expr& e, const ast::Binary& b, const ExprEnv& env) {
    auto lhs = check(*b.lhs, env);
    auto rhs = check(*b.rhs, env);
    if (!lhs || !rhs) return std::nullopt;
    using Op = ast::BinaryOp;
    static const char* opText[] = {"+", "-", "*", "/", "%", "<", "<=", ">", ">=", "==", "!=", "and", "or"};
    const std::string op = opText[static_cast<int>(b.op)];
    const Type lt = lhs->type, rt = rhs->type;
    auto fail = [&]() -> std::optional<Expr> {
        g_.diags.error(b.opSpan, "operator `" + op + "` cannot combine " + tn(lt) + " and " + tn(rt));
        return std::nullopt;
    };
    Expr r;
    r.span = e.span;
    static const ExprOp ops[] = {ExprOp::Add, ExprOp::Sub, ExprOp::Mul, ExprOp::Div, ExprOp::Mod,
                                 ExprOp::Lt,  ExprOp::Le,  ExprOp::Gt,  ExprOp::Ge,  ExprOp::Eq,
                                 ExprOp::Ne,  ExprOp::And, ExprOp::Or};
    r.op = ops[static_cast<int>(b.op)];
    const bool numeric = lt.isNumeric() && rt.isNumeric();
    const Type common = (lt.kind == TypeKind::Int && rt.kind == TypeKind::Int) ? ir::kIntType : ir::kFloatType;
    auto push = [&](Type lto, Type rto) {
        r.args.push_back(coerce(std::move(*lhs), lto));
        r.args.push_back(coerce(std::move(*rhs), rto));
    };
    switch (b.op) {
    case Op::Add:
    case Op::Sub:
        if (numeric) { r.type = common; push(common, common); return r; }
        if (lt.isVector() && lt == rt) { r.type = lt; push(lt, lt); return r; }
        if (b.op == Op::Add && lt.kind == TypeKind::String && rt.kind == TypeKind::String) {
            r.type = ir::kStringType; push(ir::kStringType, ir::kStringType); return r;
        }
        if (b.op == Op::Add && (lt.kind == TypeKind::String || rt.kind == TypeKind::String)) {
            g_.diags.error(b.opSpan, "operator `+` cannot combine " + tn(lt) + " and " + tn(rt) +
                                         "; convert with str(…) or use format(…)");
            return std::nullopt;
        }
        return fail();
    case Op::Mul:
        if (numeric) { r.type = common; push(common, common); return r; }
        if (lt.isVector() && rt.isNumeric()) { r.type = lt; push(lt, ir::kFloatType); return r; }
        if (lt.isNumeric() && rt.isVector()) { r.type = rt; push(ir::kFloatType, rt); return r; }
        if (lt.isVector() && lt == rt) {
            g_.diags.error(b.opSpan, "operator `*` cannot multiply two " + tn(lt) + "s; use dot(a, b) or cross(a, b)");
            return std::nullopt;
        }
        return fail();
    case Op::Div:
        if (numeric) { r.type = ir::kFloatType; push(ir::kFloatType, ir::kFloatType); return r; }
        if (lt.isVector() && rt.isNumeric()) { r.type = lt; push(lt, ir::kFloatType); return r; }
        return fail();
    case Op::Mod:
        if (numeric) { r.type = common; push(common, common); return r; }
        return fail();
    case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge:
        if (numeric) { r.type = ir::kBoolType; push(common, common); return r; }
        return fail();
    case Op::Eq: case Op::Ne:
        if (numeric) { r.type = ir::kBoolType; push(common, common); return r; }
        if (lt == rt && lt.kind != TypeKind::Void) { r.type = ir::kBoolType; push(lt, rt); return r; }
        return fail();
    case Op::And: case Op::Or:
        if (lt.kind == TypeKind::Bool && rt.kind == TypeKind::Bool) { r.type = ir::kBoolType; push(ir::kBoolType, ir::kBoolType); return r; }
        return fail();
    }
    return fail();
}

std::optional<Expr> ExprChecker::conditional(const ast::Expr& e, const ast::Conditional& c, const ExprEnv& env) {
    auto cond = checkAs(*c.cond, ir::kBoolType, env, "the condition of `?:`");
    auto a = check(*c.then, env);
    auto b = check(*c.otherwise, env);
    if (!cond || !a || !b) return std::nullopt;
    Type t = a->type;
    if (!(a->type == b->type)) {
        if (a->type.isNumeric() && b->type.isNumeric()) {
            t = ir::kFloatType;
        } else {
            g_.diags.error(e.span, "the two branches of `?:` have different types: " + tn(a->type) + " and " +
                                       tn(b->type));
            return std::nullopt;
        }
    }
    Expr r;
    r.op = ExprOp::Cond;
    r.type = t;
    r.span = e.span;
    r.args.push_back(std::move(*cond));
    r.args.push_back(coerce(std::move(*a), t));
    r.args.push_back(coerce(std::move(*b), t));
    return r;
}

}  // namespace g2d::sema
