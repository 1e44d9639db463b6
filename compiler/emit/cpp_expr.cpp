#include "emit/cpp_expr.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <climits>
#include <cstdio>

namespace g2d::emit {

using ir::Builtin;
using ir::ExprOp;
using ir::TypeKind;

int Places::add(const Span& s) {
    spans_.push_back(s);
    return static_cast<int>(spans_.size() - 1);
}

std::string ConstantValues::add(const std::string& valueExpr) {
    auto it = std::find(exprs_.begin(), exprs_.end(), valueExpr);
    if (it == exprs_.end()) it = exprs_.insert(exprs_.end(), valueExpr);
    return "kValue" + std::to_string(it - exprs_.begin());
}

std::string ConstantValues::definitions() const {
    std::string out;
    for (std::size_t i = 0; i < exprs_.size(); ++i) out += "    const Value kValue" + std::to_string(i) + exprs_[i] + ";\n";
    return out;
}

std::string cppType(const ir::Type& t) {
    switch (t.kind) {
    case TypeKind::Int: return "long long";
    case TypeKind::Float: return "double";
    case TypeKind::Bool: return "bool";
    case TypeKind::String: return "std::string";
    case TypeKind::Vec2: return "vec2";
    case TypeKind::Vec3: return "vec3";
    case TypeKind::Enum: return "int";
    case TypeKind::Void: return "void";
    }
    return "void";
}

std::string valueInit(const ir::Type& t, const std::string& v) {
    if (t.kind == TypeKind::Enum) return "{EnumVal{" + std::to_string(t.enumId) + ", " + v + "}}";
    return "{" + v + "}";
}

std::string valueOf(const ir::Type& t, const std::string& v) { return "Value" + valueInit(t, v); }

std::string cppStyleProp(const ir::StyleAssign& s) {
    // Property names are identifiers: safe inside a comment.
    return "StyleProp(" + std::to_string(s.propId) + " /* " + s.prop + " */)";
}

std::string cppString(const std::string& s) {
    std::string out = "std::string(\"";
    for (unsigned char c : s) {
        if (c == '"' || c == '\\') { out += '\\'; out += static_cast<char>(c); }
        else if (c == '\n') out += "\\n";
        else if (c == '\r') out += "\\r";
        else if (c == '\t') out += "\\t";
        else if (c < 0x20 || c == '?') {  // `?` avoids trigraph-like sequences
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\%03o", c);
            out += buf;
        } else out += static_cast<char>(c);
    }
    return out + "\", " + std::to_string(s.size()) + ")";
}

namespace {

std::string doubleLiteral(double x) {
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, x);
    std::string s(buf, res.ptr);
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // keep it a double
    return x < 0 || (x == 0 && std::signbit(x)) ? "(" + s + ")" : s;
}

}  // namespace

std::string cppLiteral(const ir::Value& v, const ir::Type& t) {
    if (auto* i = std::get_if<long long>(&v)) {
        if (*i == LLONG_MIN) return "(-9223372036854775807LL - 1)";
        return *i < 0 ? "(" + std::to_string(*i) + "LL)" : std::to_string(*i) + "LL";
    }
    if (auto* d = std::get_if<double>(&v)) return doubleLiteral(*d);
    if (auto* b = std::get_if<bool>(&v)) return *b ? "true" : "false";
    if (auto* s = std::get_if<std::string>(&v)) return cppString(*s);
    if (auto* p = std::get_if<ir::Vec2>(&v)) return "vec2(" + doubleLiteral(p->x) + ", " + doubleLiteral(p->y) + ")";
    if (auto* p = std::get_if<ir::Vec3>(&v))
        return "vec3(" + doubleLiteral(p->x) + ", " + doubleLiteral(p->y) + ", " + doubleLiteral(p->z) + ")";
    (void)t;
    return std::to_string(std::get<ir::EnumValue>(v).index);
}

std::string ExprGen::attrAccess(int kind, const std::string& id, ir::ElemClass cls, int attr, const std::string& graph) const {
    const char* slot = cls == ir::ElemClass::Edge ? ".edgeSlot(" : cls == ir::ElemClass::Face ? ".faceSlot(" : ".nodeSlot(";
    return "store_" + std::to_string(kind) + "[" + graph + slot + id + ")].a" +
           std::to_string(attr);
    (void)prog_;
}

std::string ExprGen::place(const ir::Expr& e, std::string& out, const std::string& indent) {
    out += indent + "loc_ = " + std::to_string(places_.add(e.span)) + ";\n";
    return "";
}

std::string ExprGen::fact(const ir::Expr& e, const std::string& id, ir::ElemClass cls, const std::string& g) {
    const char* c = cls == ir::ElemClass::Edge ? "ElemClass::Edge" : cls == ir::ElemClass::Face ? "ElemClass::Face" : "ElemClass::Node";
    return std::string("rt::fact::") + rt::elementFactEntry(e.fact).function + "(" + g + ", " + c + ", " + id + ")";
}

std::string ExprGen::display(const std::string& value, const ir::Type& t) {
    if (t.kind == TypeKind::Enum) return "std::string(enum_names_" + std::to_string(t.enumId) + "[" + value + "])";
    return "rtc::str(" + value + ")";
}

std::string ExprGen::gen(const ir::Expr& e, const ExprContext& ctx, std::string& out, const std::string& in) {
    auto bind = [&](const std::string& expr) {
        const std::string t = temp();
        out += in + "const " + cppType(e.type) + " " + t + " = " + expr + ";\n";
        return t;
    };
    switch (e.op) {
    case ExprOp::Literal: return cppLiteral(e.value, e.type);
    case ExprOp::Param: return "P_.p" + std::to_string(e.index);
    case ExprOp::Const: return "C_.c" + std::to_string(e.index);
    case ExprOp::Local: return "L" + std::to_string(e.index);
    case ExprOp::FnArg: return "a" + std::to_string(e.index);
    case ExprOp::Attr: {
        const int i = e.elem.index;
        switch (e.elem.cls) {
        case ir::ElemClass::Edge: return bind(attrAccess(ctx.edgeKind(i), ctx.edge(i), e.elem.cls, e.index, ctx.graph));
        case ir::ElemClass::Face: return bind(attrAccess(ctx.faceKind(i), ctx.face(i), e.elem.cls, e.index, ctx.graph));
        case ir::ElemClass::Node: break;
        }
        return bind(attrAccess(ctx.nodeKind(i), ctx.node(i), e.elem.cls, e.index, ctx.graph));
    }
    case ExprOp::SelfAttr: return bind(attrAccess(ctx.selfKind, ctx.self, ctx.selfClass, e.index, ctx.graph));
    case ExprOp::Fact: {
        const int i = e.elem.index;
        const ir::ElemClass cls = e.elem.cls;
        return bind(fact(e, cls == ir::ElemClass::Edge ? ctx.edge(i) : cls == ir::ElemClass::Face ? ctx.face(i) : ctx.node(i), cls, ctx.graph));
    }
    case ExprOp::SelfFact: return bind(fact(e, ctx.self, ctx.selfClass, ctx.graph));
    case ExprOp::Placed: return bind("*placed[" + std::to_string(e.index) + "]");
    case ExprOp::CompoundValue:
        return bind("std::get<" + cppType(e.type) + ">(rt::compoundValue(" + ctx.graph + ", " + std::to_string(e.index) + ", " +
                    std::to_string(e.slot) + "))");
    case ExprOp::Count: return "counts[" + std::to_string(e.index) + "]";
    case ExprOp::VecX: return bind("(" + gen(e.args[0], ctx, out, in) + ").x");
    case ExprOp::VecY: return bind("(" + gen(e.args[0], ctx, out, in) + ").y");
    case ExprOp::VecZ: return bind("(" + gen(e.args[0], ctx, out, in) + ").z");
    case ExprOp::Neg: {
        const std::string v = gen(e.args[0], ctx, out, in);
        if (e.type.kind == TypeKind::Int) {
            place(e, out, in);
            return bind("rt::negInt(" + v + ")");
        }
        return bind("-" + v);
    }
    case ExprOp::Not: return bind("!" + gen(e.args[0], ctx, out, in));
    case ExprOp::And:
    case ExprOp::Or: {
        const std::string l = gen(e.args[0], ctx, out, in);
        const std::string t = temp();
        out += in + "bool " + t + " = " + l + ";\n";
        out += in + "if (" + (e.op == ExprOp::And ? "" : "!") + t + ") {\n";
        const std::string r = gen(e.args[1], ctx, out, in + "    ");
        out += in + "    " + t + " = " + r + ";\n" + in + "}\n";
        return t;
    }
    case ExprOp::Cond: {
        const std::string c = gen(e.args[0], ctx, out, in);
        const std::string t = temp();
        out += in + cppType(e.type) + " " + t + "{};\n";
        out += in + "if (" + c + ") {\n";
        const std::string a = gen(e.args[1], ctx, out, in + "    ");
        out += in + "    " + t + " = " + a + ";\n" + in + "} else {\n";
        const std::string b = gen(e.args[2], ctx, out, in + "    ");
        out += in + "    " + t + " = " + b + ";\n" + in + "}\n";
        return t;
    }
    case ExprOp::Call: return call(e, ctx, out, in);
    case ExprOp::CallFn: {
        std::vector<std::string> args;
        for (const auto& a : e.args) args.push_back(gen(a, ctx, out, in));
        std::string c = "fn_" + std::to_string(e.index) + "(";
        for (std::size_t i = 0; i < args.size(); ++i) c += (i ? ", " : "") + args[i];
        return bind(c + ")");
    }
    case ExprOp::Add:
    case ExprOp::Sub:
    case ExprOp::Mul:
    case ExprOp::Div:
    case ExprOp::Mod:
    case ExprOp::Lt:
    case ExprOp::Le:
    case ExprOp::Gt:
    case ExprOp::Ge:
    case ExprOp::Eq:
    case ExprOp::Ne: return binary(e, ctx, out, in);
    }
    throw std::logic_error("an expression operation out of range");
}

std::string ExprGen::binary(const ir::Expr& e, const ExprContext& ctx, std::string& out, const std::string& in) {
    const std::string l = gen(e.args[0], ctx, out, in);
    const std::string r = gen(e.args[1], ctx, out, in);
    const TypeKind lk = e.args[0].type.kind, rk = e.args[1].type.kind;
    auto bind = [&](const std::string& expr, bool checked) {
        if (checked) place(e, out, in);
        const std::string t = temp();
        out += in + "const " + cppType(e.type) + " " + t + " = " + expr + ";\n";
        return t;
    };
    auto cmp = [&](const char* op) { return bind("(" + l + " " + op + " " + r + ")", false); };
    switch (e.op) {
    case ExprOp::Lt: return cmp("<");
    case ExprOp::Le: return cmp("<=");
    case ExprOp::Gt: return cmp(">");
    case ExprOp::Ge: return cmp(">=");
    case ExprOp::Eq: return cmp("==");
    case ExprOp::Ne: return cmp("!=");
    default: break;
    }
    if (lk == TypeKind::Int && rk == TypeKind::Int) {
        const char* fn = e.op == ExprOp::Add ? "addInt" : e.op == ExprOp::Sub ? "subInt" : e.op == ExprOp::Mul ? "mulInt" : "modInt";
        return bind(std::string(fn) + "(" + l + ", " + r + ")", true);
    }
    if (lk == TypeKind::Float && rk == TypeKind::Float) {
        switch (e.op) {
        case ExprOp::Add: return bind("rt::finite(" + l + " + " + r + ")", true);
        case ExprOp::Sub: return bind("rt::finite(" + l + " - " + r + ")", true);
        case ExprOp::Mul: return bind("rt::finite(" + l + " * " + r + ")", true);
        case ExprOp::Div: return bind("rt::divFloat(" + l + ", " + r + ")", true);
        default: return bind("rt::modFloat(" + l + ", " + r + ")", true);
        }
    }
    const bool lv = e.args[0].type.isVector(), rv = e.args[1].type.isVector();
    if (lv && rv) return bind("rt::finite(" + l + (e.op == ExprOp::Add ? " + " : " - ") + r + ")", true);
    if (lv && rk == TypeKind::Float)
        return e.op == ExprOp::Mul ? bind("rt::finite(" + l + " * " + r + ")", true) : bind("rt::divVec(" + l + ", " + r + ")", true);
    if (lk == TypeKind::Float && rv) return bind("rt::finite(" + l + " * " + r + ")", true);
    return bind(l + " + " + r, false);  // strings
}

std::string ExprGen::call(const ir::Expr& e, const ExprContext& ctx, std::string& out, const std::string& in) {
    // Arguments first, left to right, as the interpreter evaluates them.
    std::vector<std::string> a;
    for (const auto& arg : e.args) a.push_back(gen(arg, ctx, out, in));
    auto bind = [&](const std::string& expr, bool checked) {
        if (checked) place(e, out, in);
        const std::string t = temp();
        out += in + "const " + cppType(e.type) + " " + t + " = " + expr + ";\n";
        return t;
    };
    const rt::BuiltinEntry& fn = rt::builtinEntry(e.builtin);
    const std::string name = std::string("rt::fn::") + fn.cppName;
    switch (fn.call) {
    case rt::BuiltinCall::Pure:
    case rt::BuiltinCall::Random: {
        std::string call = name + "(" + (fn.call == rt::BuiltinCall::Random ? "*rng_" : "");
        for (std::size_t i = 0; i < a.size(); ++i) call += (i || fn.call == rt::BuiltinCall::Random ? ", " : "") + a[i];
        return bind(call + ")", fn.mayFail);
    }
    case rt::BuiltinCall::Variadic: {
        std::string call = a[0];
        for (std::size_t i = 1; i < a.size(); ++i) call = name + "(" + call + ", " + a[i] + ")";
        return bind(call, fn.mayFail);
    }
    case rt::BuiltinCall::Special: break;
    }
    switch (e.builtin) {
    case Builtin::ToStr: return bind(display(a[0], e.args[0].type), false);
    case Builtin::Format: {
        const std::string h = temp();
        out += in + "const FormatHole " + h + "[] = {";
        for (std::size_t i = 1; i < a.size(); ++i) {
            if (i > 1) out += ", ";
            const auto& t = e.args[i].type;
            out += t.kind == TypeKind::Enum ? "FormatHole{" + display(a[i], t) + ", 0, 0, 0}" : "rtc::hole(" + a[i] + ")";
        }
        if (a.size() == 1) out += "FormatHole{}";
        out += "};\n";
        return bind("rt::formatTemplate(" + a[0] + ", " + h + ", " + std::to_string(a.size() - 1) + ")", true);
    }
    case Builtin::Choice: {
        const std::string arr = temp();
        out += in + "const " + cppType(e.type) + " " + arr + "[] = {";
        for (std::size_t i = 0; i < a.size(); ++i) out += (i ? ", " : "") + a[i];
        out += "};\n";
        return bind(arr + "[rt::fn::choiceIndex(*rng_, " + std::to_string(a.size()) + ")]", false);
    }
    default: break;
    }
    throw std::logic_error("the emitter has no form for built-in `" + std::string(fn.cppName) + "`");
}

}  // namespace g2d::emit
