#include "sema/decl_checker.hpp"

#include "g2d/graph.hpp"

#include <set>

#include "sema/builtins.hpp"
#include "sema/const_fold.hpp"
#include "sema/param_range_checker.hpp"

namespace g2d::sema {

using ir::Type;
using ir::TypeKind;

namespace {

// How deep calls nest below `e` (0: no call), from the depths of the
// functions declared so far.
constexpr int kMaxCallDepth = 100;
int deepestCall(const ir::Expr& e, const std::vector<int>& functionDepth) {
    int deepest = 0;
    if (e.op == ir::ExprOp::CallFn && static_cast<std::size_t>(e.index) < functionDepth.size())
        deepest = functionDepth[static_cast<std::size_t>(e.index)];
    for (const auto& a : e.args) deepest = std::max(deepest, deepestCall(a, functionDepth));
    return deepest;
}

const std::set<std::string> kKnownTags = {"circle", "line", "rect", "path", "image", "text", "polyline", "polygon", "none"};

ir::Expr zeroValue(const Type& t, Span span) {
    ir::Expr e;
    e.op = ir::ExprOp::Literal;
    e.type = t;
    e.span = span;
    switch (t.kind) {
    case TypeKind::Int: e.value = 0LL; break;
    case TypeKind::Float: e.value = 0.0; break;
    case TypeKind::Bool: e.value = false; break;
    case TypeKind::String: e.value = std::string(); break;
    case TypeKind::Vec2: e.value = ir::Vec2{}; break;
    case TypeKind::Vec3: e.value = ir::Vec3{}; break;
    case TypeKind::Enum: e.value = ir::EnumValue{t.enumId, 0}; break;
    case TypeKind::Void: break;
    }
    return e;
}

ExprEnv constantEnv(const std::string& context) {
    ExprEnv env;
    env.context = context;
    env.allowRandom = false;
    env.allowElements = false;
    env.allowLocals = false;
    return env;
}

}  // namespace

const std::set<std::string>& reservedAttributeNames() {
    static const std::set<std::string> names = {"pos", "age", "id", "degree", "in_degree", "out_degree", "style", "kind"};
    return names;
}

const std::set<std::string>& valueTypeNames() {
    static const std::set<std::string> names = {"int", "float", "bool", "string", "vec2", "vec3"};
    return names;
}

std::optional<Type> resolveType(Globals& g, const ast::TypeRef& t) {
    const std::string& n = t.name.name;
    if (n == "int") return Type::of(TypeKind::Int);
    if (n == "float") return Type::of(TypeKind::Float);
    if (n == "bool") return Type::of(TypeKind::Bool);
    if (n == "string") return Type::of(TypeKind::String);
    if (n == "vec2") return Type::of(TypeKind::Vec2);
    if (n == "vec3") return Type::of(TypeKind::Vec3);
    if (auto it = g.enums.find(n); it != g.enums.end()) return Type::enumeration(it->second);
    std::vector<std::string> candidates(valueTypeNames().begin(), valueTypeNames().end());
    for (const auto& [k, v] : g.enums) candidates.push_back(k);
    if (g.kinds.count(n))
        g.diags.error(t.name.span, "`" + n + "` is a kind, not a value type (types are int, float, bool, string, vec2, "
                                   "vec3 and enums)");
    else
        g.diags.error(t.name.span, "unknown type `" + n + "`" + suggest(n, candidates));
    return std::nullopt;
}

bool declareTopLevel(Globals& g, const ast::Ident& name, const std::string& what) {
    if (findBuiltin(name.name) || name.name == "pi" || name.name == "tau") {
        g.diags.error(name.span, what + " `" + name.name + "` would hide the built-in `" + name.name + "`");
        return false;
    }
    if (valueTypeNames().count(name.name)) {
        g.diags.error(name.span, what + " `" + name.name + "` would hide the built-in type `" + name.name + "`");
        return false;
    }
    auto [it, inserted] = g.topLevel.emplace(name.name, name.span);
    if (!inserted) {
        auto& d = g.diags.error(name.span, "`" + name.name + "` is already declared");
        d.notes.push_back({it->second, "previous declaration of `" + name.name + "` is here"});
        return false;
    }
    return true;
}

void declareEnum(Globals& g, const ast::EnumDecl& d) {
    if (!declareTopLevel(g, d.name, "enum")) return;
    const int id = static_cast<int>(g.prog.enums.size());
    ir::Enum en;
    en.name = d.name.name;
    std::map<std::string, Span> seen;
    for (const auto& v : d.values) {
        if (auto [it, inserted] = seen.emplace(v.name, v.span); !inserted) {
            auto& diag = g.diags.error(v.span, "enum `" + en.name + "` already has a value `" + v.name + "`");
            diag.notes.push_back({it->second, "first declared here"});
            continue;
        }
        g.enumerators[v.name].push_back(ir::EnumValue{id, static_cast<int>(en.values.size())});
        en.values.push_back(v.name);
    }
    g.enums[en.name] = id;
    g.prog.enums.push_back(std::move(en));
}

void declareKindName(Globals& g, const ast::KindDecl& d) {
    if (g.prog.kinds.size() >= rt::kMaxKinds) {
        if (!g.tooManyKinds)
            g.diags.error(d.name.span, "too many kinds: a grammar may declare at most " + std::to_string(rt::kMaxKinds) +
                                           " node, edge and face kinds");
        g.tooManyKinds = true;
        return;
    }
    using Class = ast::KindDecl::Class;
    const ir::ElemClass cls = d.cls == Class::Edge ? ir::ElemClass::Edge : d.cls == Class::Face ? ir::ElemClass::Face : ir::ElemClass::Node;
    if (!declareTopLevel(g, d.name, std::string(elemClassName(cls)) + " kind")) return;
    ir::Kind k;
    k.name = d.name.name;
    k.cls = cls;
    k.directed = cls == ir::ElemClass::Edge && d.directed.value_or(false);
    k.oriented = d.option && d.option->name == "oriented";
    k.span = d.span;
    g.kinds[k.name] = static_cast<int>(g.prog.kinds.size());
    g.prog.kinds.push_back(std::move(k));
}

void checkParam(Globals& g, ExprChecker& ec, const ast::ParamDecl& d) {
    auto type = resolveType(g, d.type);
    if (!declareTopLevel(g, d.name, "parameter")) return;
    if (!type) return;
    ExprEnv env = constantEnv("a parameter's default value");
    auto value = ec.checkAs(*d.value, *type, env, "the default of parameter `" + d.name.name + "`");
    ir::Param p;
    p.name = d.name.name;
    p.type = *type;
    p.span = d.span;
    bool defaultKnown = false;
    if (value) {
        std::string error;
        auto folded = fold(*value, g.prog, &error);
        if (!error.empty()) {
            g.diags.error(d.value->span, error + " in the default of parameter `" + d.name.name + "`");
        } else if (!folded) {
            g.diags.error(d.value->span, "the default of parameter `" + d.name.name +
                                             "` must be a constant (literals and constants only)");
        } else {
            p.defaultValue = *folded;
            defaultKnown = true;
        }
    }
    checkParamRange(g, ec, d, p, defaultKnown);
    g.params[p.name] = static_cast<int>(g.prog.params.size());
    g.paramUsed.push_back(false);
    g.paramFile.push_back(d.name.span.file);
    g.prog.params.push_back(std::move(p));
}

void checkConst(Globals& g, ExprChecker& ec, const ast::ConstDecl& d) {
    std::optional<Type> type;
    if (d.type) type = resolveType(g, *d.type);
    const bool declared = declareTopLevel(g, d.name, "constant");
    ExprEnv env;
    env.context = "a constant";
    env.allowElements = false;
    env.allowLocals = false;
    g.definingConst = d.name.name;
    std::optional<ir::Expr> value = type ? ec.checkAs(*d.value, *type, env, "constant `" + d.name.name + "`")
                                         : ec.check(*d.value, env);
    g.definingConst.clear();
    if (!declared) return;
    ir::Const c;
    c.name = d.name.name;
    c.span = d.span;
    if (value) {
        c.type = value->type;
        std::string error;
        c.folded = fold(*value, g.prog, &error);
        if (!error.empty()) g.diags.error(d.value->span, error + " in constant `" + c.name + "`");
        c.value = std::move(*value);
    } else {
        c.type = Type::of(TypeKind::Void);  // poisoned: uses stay silent, the error is reported
    }
    const int index = static_cast<int>(g.prog.consts.size());
    g.consts[c.name] = index;
    g.constUsed.push_back(false);
    g.constFile.push_back(d.name.span.file);
    g.prog.consts.push_back(std::move(c));
    g.constsDeclared = index + 1;
}

void checkFunction(Globals& g, ExprChecker& ec, const ast::FnDecl& d) {
    if (!declareTopLevel(g, d.name, "function")) return;
    ir::Function fn;
    fn.name = d.name.name;
    fn.span = d.span;
    std::vector<LocalVar> locals;
    bool ok = true;
    for (const auto& p : d.params) {
        for (const auto& l : locals)
            if (l.name == p.name.name) {
                g.diags.error(p.name.span, "function `" + fn.name + "` already has a parameter `" + p.name.name + "`");
                ok = false;
            }
        auto t = resolveType(g, p.type);
        if (!t) { ok = false; continue; }
        locals.push_back(LocalVar{p.name.name, *t, static_cast<int>(locals.size()), true, p.name.span, false});
        fn.paramNames.push_back(p.name.name);
        fn.paramTypes.push_back(*t);
    }
    auto result = resolveType(g, d.result);
    const int index = static_cast<int>(g.prog.functions.size());
    g.functions[fn.name] = index;
    g.functionsDeclared = index;  // the body may not call the function itself
    fn.result = result.value_or(Type::of(TypeKind::Void));
    g.prog.functions.push_back(fn);
    if (ok && result) {
        ExprEnv env;
        env.context = "a function body";
        env.allowElements = false;
        env.locals = &locals;
        auto body = ec.checkAs(*d.body, *result, env, "the result of function `" + fn.name + "`");
        if (body) {
            // Calls nest at most kMaxCallDepth deep: evaluation recurses once per level.
            const int depth = 1 + deepestCall(*body, g.functionDepth);
            if (depth == kMaxCallDepth + 1)  // (deeper ones call this one: reported once)
                g.diags.error(d.name.span, "function `" + fn.name + "` nests calls " + std::to_string(depth) +
                                               " deep (at most " + std::to_string(kMaxCallDepth) + ")");
            g.prog.functions[index].body = std::move(*body);
        }
        for (const auto& l : locals)
            if (!l.used && l.span.file == g.mainFile)
                g.diags.warning(l.span, "parameter `" + l.name + "` of function `" + fn.name + "` is never used");
    }
    g.functionDepth.resize(static_cast<std::size_t>(index) + 1, 1);
    g.functionDepth[static_cast<std::size_t>(index)] = 1 + deepestCall(g.prog.functions[index].body, g.functionDepth);
    g.functionsDeclared = index + 1;
}

void checkStyleValue(Globals& g, const std::string& prop, const ir::Expr& value) {
    if (value.type.isVector() || value.type.kind == TypeKind::Void) {
        g.diags.error(value.span, "style property `" + prop + "` must be a number, bool, string or enum, not " +
                                      g.typeName(value.type));
        return;
    }
    if (prop == "tag") {
        if (value.type.kind != TypeKind::String) {
            g.diags.error(value.span, "style property `tag` must be a string (one of circle, line, rect, path, image, "
                                      "text, polyline, none)");
            return;
        }
        if (auto v = fold(value, g.prog)) {
            const auto& s = std::get<std::string>(*v);
            if (!kKnownTags.count(s))
                g.diags.error(value.span, "unknown drawing tag \"" + s +
                                              "\" (use circle, line, rect, path, image, text, polyline or none)");
        }
    }
}

void checkKindBody(Globals& g, ExprChecker& ec, const ast::KindDecl& d) {
    auto it = g.kinds.find(d.name.name);
    if (it == g.kinds.end()) return;
    const int kindIndex = it->second;
    if (g.prog.kinds[kindIndex].span.line != d.span.line || g.prog.kinds[kindIndex].span.file != d.span.file)
        return;  // a duplicate declaration, already reported
    if (d.cls != ast::KindDecl::Class::Edge && d.directed.has_value()) {
        g.diags.error(d.name.span, "only edge kinds can be directed or undirected");
    }
    if (d.option && d.option->name != "oriented")
        g.diags.error(d.option->span, "unknown face kind option `" + d.option->name +
                                          "`: a face kind may be `oriented` (a new face takes its neighbours' orientation)");
    std::map<std::string, Span> seen;
    for (const auto& a : d.attrs) {
        auto type = resolveType(g, a.type);
        if (reservedAttributeNames().count(a.name.name)) {
            g.diags.error(a.name.span, "`" + a.name.name + "` is a built-in fact of every element and cannot be "
                                                           "declared as an attribute");
            continue;
        }
        if (auto [sit, inserted] = seen.emplace(a.name.name, a.name.span); !inserted) {
            auto& diag = g.diags.error(a.name.span, "kind `" + d.name.name + "` already has an attribute `" +
                                                        a.name.name + "`");
            diag.notes.push_back({sit->second, "first declared here"});
            continue;
        }
        if (!type) continue;
        ir::Attribute attr;
        attr.name = a.name.name;
        attr.type = *type;
        attr.span = a.span;
        if (a.value) {
            ExprEnv env = constantEnv("an attribute default");
            auto v = ec.checkAs(*a.value, *type, env, "the default of `" + a.name.name + "`");
            // Keep a badly initialised attribute declared, so its uses do not cascade.
            attr.defaultValue = v ? std::move(*v) : zeroValue(*type, a.span);
        } else {
            attr.defaultValue = zeroValue(*type, a.span);
        }
        g.prog.kinds[kindIndex].attrs.push_back(std::move(attr));
    }
    std::set<std::string> styleSeen;
    for (const auto& s : d.style) {
        if (!styleSeen.insert(s.name.name).second) {
            g.diags.error(s.name.span, "style property `" + s.name.name + "` is set twice");
            continue;
        }
        ExprEnv env;
        env.context = "a kind's style";
        env.allowRandom = false;
        env.allowLocals = false;
        env.allowElements = false;
        env.selfKind = kindIndex;
        auto v = ec.check(*s.value, env);
        if (!v) continue;
        checkStyleValue(g, s.name.name, *v);
        g.prog.kinds[kindIndex].style.push_back(ir::StyleProp{s.name.name, std::move(*v), s.span});
    }
}

std::optional<ir::Expr> checkCount(Globals& g, ExprChecker& ec, const ast::Expr& value, const std::string& what) {
    ExprEnv env = constantEnv(what);
    auto v = ec.checkAs(value, Type::of(TypeKind::Int), env, what);
    if (!v) return std::nullopt;
    std::string error;
    auto f = fold(*v, g.prog, &error);
    if (!error.empty()) g.diags.error(value.span, error + " in " + what);
    else if (f && std::get<long long>(*f) < 0) g.diags.error(value.span, what + " cannot be negative");
    return v;
}

std::optional<ir::Expr> checkStepLimit(Globals& g, ExprChecker& ec, const ast::Expr& value) { return checkCount(g, ec, value, "a step limit"); }

void checkLimit(Globals& g, ExprChecker& ec, const ast::LimitDecl& d, bool& seen) {
    if (seen) {
        g.diags.error(d.span, "the global step limit is set twice");
        return;
    }
    seen = true;
    g.prog.stepLimit = checkStepLimit(g, ec, *d.value);
}

void checkMerge(Globals& g, ExprChecker& ec, const ast::MergeDecl& d) {
    if (g.prog.mergeAll) {
        g.diags.error(d.span, "`merge within` is set twice");
        return;
    }
    g.prog.mergeAll = true;
    ExprEnv env = constantEnv("a merge tolerance");
    auto v = ec.checkAs(*d.tolerance, ir::kFloatType, env, "a merge tolerance");
    if (!v) return;
    if (auto f = fold(*v, g.prog); f && std::get<double>(*f) < 0)
        g.diags.error(d.tolerance->span, "a merge tolerance cannot be negative (0 turns merging off)");
    g.prog.mergeTolerance = std::move(*v);
}

void checkPriority(Globals& g, ExprChecker& ec, const ast::PriorityDecl& d) {
    if (d.priorityOverflow) {
        g.diags.error(d.prioritySpan, "priority is out of range (64-bit integers)");
        return;
    }
    for (const auto& s : d.repeatedOptions) g.diags.error(s, "option given twice for priority " + std::to_string(d.priority));
    for (const auto& w : d.unknownOptions)
        g.diags.error(w.span, "unknown priority option `" + w.name + "` (options: limit N, parallel, generation)" +
                                  suggest(w.name, {"limit", "parallel", "generation"}));
    if (g.prog.priorities.count(d.priority)) {
        auto& diag = g.diags.error(d.prioritySpan, "priority " + std::to_string(d.priority) + " is configured twice");
        diag.notes.push_back({g.prog.priorities[d.priority].span, "first configured here"});
        return;
    }
    ir::PriorityConfig cfg;
    cfg.parallel = d.parallel;
    cfg.generation = d.generation;
    cfg.span = d.prioritySpan;
    if (d.limit) cfg.limit = checkStepLimit(g, ec, *d.limit);
    g.prog.priorities[d.priority] = std::move(cfg);
}

}  // namespace g2d::sema
