// Python (model_gen) expressions to g2d expressions: python_parse.cpp builds the
// tree, this file types it and writes the g2d text (docs/language.md §10, §13).
#include "import/python_expr.hpp"

#include <cctype>
#include <exception>
#include <set>
#include <utility>

#include "import/model_gen_styles.hpp"
#include "import/python_translator.hpp"


namespace g2d::import::translation {

Out Translator::expr(const Node& n) {
    Out o = bare(n);
    if (n.parenthesized && o.level > kPrimary) o = {"(" + o.text + ")", o.type, kPrimary};
    return o;
}

Out Translator::bare(const Node& n) {
    switch (n.kind) {
        case K::Int: return {n.text, T::Int, kPrimary};
        case K::Float: return {n.text, T::Float, kPrimary};
        case K::Str: return {"\"" + escapeString(n.text, false) + "\"", T::String, kPrimary};
        case K::Bool: return {n.text == "True" ? "true" : "false", T::Bool, kPrimary};
        case K::None: return {"none", T::None, kPrimary};
        case K::FStr: return fstring(n);
        case K::Name: return nameValue(n);
        case K::Attr: return attribute(n);
        case K::Subscript: return subscript(n);
        case K::Call: return callExpr(n);
        case K::Unary: return unary(n);
        case K::Not: return negate(expr(*n.kids[0]), n.column);
        case K::Binary: {
            const Out l = expr(*n.kids[0]);  // left first: the first problem is reported
            const Out r = expr(*n.kids[1]);
            return arithmetic(n.text, l, r, n.column, n.text == "//" && !random(n));
        }
        case K::BoolOp: return boolOp(n);
        case K::Compare: return compare(n);
        case K::IfExp: return conditional(n);
        case K::Tuple: fail(n.column, "tuples are not values in g2d; a vector is `Vec(x1=a, y1=b)`");
        case K::List: fail(n.column, "lists are not supported");
    }
    fail(n.column, "unsupported expression");
}

bool Translator::random(const Node& n) {
    if (n.kind == K::Call && n.kids[0]->kind == K::Attr && n.kids[0]->kids[0]->kind == K::Name &&
        n.kids[0]->kids[0]->text == "random")
        return true;
    for (const py::NodePtr& k : n.kids)
        if (random(*k)) return true;
    return false;
}

std::optional<Ref> Translator::resolve(const std::string& name) {
    if (c_.lookup) {
        if (std::optional<PyBinding> b = c_.lookup(name)) {
            const Ref::Kind kind = b->kind == PyBinding::Kind::Element ? Ref::Kind::Element
                                   : b->kind == PyBinding::Kind::Placed ? Ref::Kind::Placed
                                                                        : Ref::Kind::Value;
            return Ref{kind, *b};
        }
    }
    if (!c_.conditionElement.empty() && name == "attr") return Ref{Ref::Kind::Attr, {}};
    if (!c_.conditionElement.empty() && name == "attrs") return Ref{Ref::Kind::Attrs, {}};
    if (name == "pi") return Ref{Ref::Kind::Value, {PyBinding::Kind::Value, "pi", T::Float, true}};
    if (kModules.count(name)) return Ref{Ref::Kind::Module, {}};
    if (kFunctions.count(name)) return Ref{Ref::Kind::Function, {}};
    return std::nullopt;
}

Out Translator::nameValue(const Node& n) {
    const std::optional<Ref> r = resolve(n.text);
    if (!r) fail(n.column, "unknown name `" + n.text + "`");
    switch (r->kind) {
        case Ref::Kind::Value:
            if (r->binding.text.empty()) fail(n.column, "`" + n.text + "` has no g2d expression");
            return {r->binding.text, r->binding.type, levelOf(r->binding.text)};
        case Ref::Kind::Element:
            fail(n.column, "`" + n.text + "` is a matched element, not a value; read an attribute (`" + n.text +
                               ".attr['key']`)" + (r->binding.isNode ? " or its position (`Vec(" + n.text + ")`)" : ""));
        case Ref::Kind::Placed: fail(n.column, "`" + n.text + "` is supported only as `Vec(" + n.text + ")`");
        case Ref::Kind::Module: fail(n.column, "the module `" + n.text + "` is not a value");
        case Ref::Kind::Function: fail(n.column, "the function `" + n.text + "` is not a value; call it");
        case Ref::Kind::Attr:
            return attributeRead(c_.conditionElement, c_.conditionElementIsNode, c_.conditionKey, n.column);
        case Ref::Kind::Attrs: fail(n.column, "`attrs` is supported only as `attrs['key']`");
    }
    fail(n.column, "unknown name `" + n.text + "`");
}

Out Translator::attributeRead(const std::string& elem, bool isNode, const std::string& key, int column) {
    if (key == "x" || key == "y") {
        if (!isNode) fail(column, "an edge has no `" + key + "`");
        return {elem + ".pos." + key, T::Float, kMember};
    }
    if (key.starts_with(".svg_") || key.starts_with(".svgx_"))
        fail(column, "the style property `" + key + "` cannot be read in g2d; store the value in an attribute");
    if (key == ".generation")
        fail(column, "`.generation` has no g2d counterpart (g2d's `age` is the step that created the element)");
    if (key.starts_with(".")) fail(column, "the tool's key `" + key + "` cannot be read in g2d");
    if (!isIdentifier(key)) fail(column, "the attribute key `" + key + "` is not a g2d name");
    const T type = c_.attributeType ? c_.attributeType(isNode, key) : T::Unknown;
    if (type == T::Unknown || type == T::None)
        fail(column, std::string("the grammar has no ") + (isNode ? "node" : "edge") + " attribute `" + key + "`");
    return {elem + "." + key, type, kMember};
}

Out Translator::attribute(const Node& n) {
    const Node& obj = *n.kids[0];
    const std::string& a = n.text;
    const bool xy = a == "x" || a == "y";
    if (obj.kind == K::Name) {
        const std::optional<Ref> r = resolve(obj.text);
        if (r && r->kind == Ref::Kind::Module) return moduleConstant(obj.text, a, obj.column);
        if (r && r->kind == Ref::Kind::Element) {
            if (xy && r->binding.isNode) return {r->binding.text + ".pos." + a, T::Float, kMember};
            if (a == "attr") fail(n.column, "`" + obj.text + ".attr` is supported only as `" + obj.text + ".attr['key']`");
            fail(n.column, "`." + a + "` of a matched element is not supported; read `" + obj.text + ".attr['" + a + "']`");
        }
        if (r && r->kind == Ref::Kind::Placed) {
            if (xy) return {"placed." + a, T::Float, kMember};
            fail(obj.column, "`" + obj.text + "` is supported only as `Vec(" + obj.text + ")`");
        }
    }
    const Out v = expr(obj);
    if (!xy) fail(n.column, "the attribute `." + a + "` is not supported");
    if (!isVec(v.type)) fail(n.column, "`." + a + "` needs a vector, got " + name(v.type));
    return {atMost(v, kMember) + "." + a, T::Float, kMember};
}

Out Translator::moduleConstant(const std::string& module, const std::string& a, int column) {
    if (module == "math" || module == "np" || module == "numpy") {
        if (a == "pi") return {"pi", T::Float, kPrimary};
        if (a == "tau") return {"tau", T::Float, kPrimary};
        if (a == "e") return {"exp(1.0)", T::Float, kPrimary};
    }
    if (numericFunction(module, a) || (module == "random" && a == "choice"))
        fail(column, "`" + module + "." + a + "` is a function; call it");
    fail(column, "`" + module + "." + a + "` has no g2d counterpart");
}

Out Translator::subscript(const Node& n) {
    const Node& base = *n.kids[0];
    const Node& index = *n.kids[1];
    auto key = [&]() -> const std::string& {
        if (index.kind != K::Str) fail(index.column, "the attribute key must be a string literal");
        return index.text;
    };
    if (base.kind == K::Attr && base.text == "attr" && base.kids[0]->kind == K::Name) {
        const Node& obj = *base.kids[0];
        const std::optional<Ref> r = resolve(obj.text);
        if (r && r->kind == Ref::Kind::Element) return attributeRead(r->binding.text, r->binding.isNode, key(), index.column);
        if (r && r->kind == Ref::Kind::Placed)
            fail(obj.column, "reading the attributes of `" + obj.text + "` is not supported; use the matched element's");
    }
    if (base.kind == K::Name) {
        const std::optional<Ref> r = resolve(base.text);
        if (r && r->kind == Ref::Kind::Attrs)
            return attributeRead(c_.conditionElement, c_.conditionElementIsNode, key(), index.column);
    }
    fail(n.column, std::string("subscripts are supported only as `X.attr['key']`") +
                       (c_.conditionElement.empty() ? "" : " and `attrs['key']`"));
}

Out Translator::unary(const Node& n) {
    const Out v = expr(*n.kids[0]);
    if (n.text == "~") fail(n.column, "the bitwise operator `~` is not supported");
    if (!isNum(v.type) && v.type != T::Vec2)
        fail(n.column, "unary `" + n.text + "` needs a number or a vector, got " + name(v.type));
    if (n.text == "+") return v;
    return {"-" + atMost(v, kMember), v.type, kPrefix};
}

Out Translator::negate(const Out& v, int column) {
    switch (v.type) {
        // Unknown: taken as bool, the tool's grammars apply `not` to flags.
        case T::Bool: case T::Unknown: return {"!" + atMost(v, kMember), T::Bool, kPrefix};
        case T::Int: case T::Float: return {below(v, kRel) + " == 0", T::Bool, kEq};
        case T::String: return {below(v, kRel) + " == \"\"", T::Bool, kEq};
        default: fail(column, "`not` of a " + name(v.type) + " has no g2d counterpart");
    }
}

Out Translator::truth(const Out& v, int column) {
    switch (v.type) {
        case T::Bool: case T::Unknown: return v;
        case T::Int: case T::Float: return {below(v, kRel) + " != 0", T::Bool, kEq};
        case T::String: return {below(v, kRel) + " != \"\"", T::Bool, kEq};
        default: fail(column, "the truth of a " + name(v.type) + " has no g2d counterpart");
    }
}

Out Translator::arithmetic(const std::string& op, const Out& l, const Out& r, int column, bool repeatable) {
    const T a = l.type, b = r.type;
    auto bad = [&](const std::string& hint) {
        fail(column, "`" + op + "` cannot combine " + name(a) + " and " + name(b) + hint);
    };
    if (op == "|" || op == "&" || op == "^" || op == "<<" || op == ">>" || op == "@")
        fail(column, "the operator `" + op + "` is not supported" +
                         (op == "|" ? "; for bools write `or`" : op == "&" ? "; for bools write `and`" : ""));
    if (a == T::None || b == T::None) fail(column, "`None` has no g2d value");
    if (a == T::Bool || b == T::Bool) bad("; arithmetic on bools needs int(…) in g2d");
    const bool strings = a == T::String || b == T::String;
    if (op == "+" || op == "-") {
        if (isNum(a) && isNum(b)) return binaryText(l, op, r, kAdd, numResult(a, b));
        if (isVec(a) && isVec(b)) return binaryText(l, op, r, kAdd, T::Vec2);
        if (op == "+" && (a == T::String || a == T::Unknown) && (b == T::String || b == T::Unknown))
            return binaryText(l, op, r, kAdd, T::String);
        bad(strings ? "; convert with str(…) or use an f-string" : "");
    }
    if (op == "*") {
        if (a == T::Vec2 && b == T::Vec2) return call("dot", {l, r}, T::Float);  // the tool's Vec * Vec
        if (isNum(a) && isNum(b)) return binaryText(l, op, r, kMul, numResult(a, b));
        if ((a == T::Vec2 && isNum(b)) || (isNum(a) && b == T::Vec2)) return binaryText(l, op, r, kMul, T::Vec2);
        bad(strings ? "; string repetition has no g2d counterpart" : "");
    }
    if (op == "/") {
        // g2d's `/` always divides as float (§10.2), like Python 3's.
        if (isNum(a) && isNum(b)) return binaryText(l, op, r, kMul, T::Float);
        if (a == T::Vec2 && isNum(b)) return binaryText(l, op, r, kMul, T::Vec2);
        bad("");
    }
    if (op == "//") {
        if (!isNum(a) || !isNum(b)) bad("");
        // floor(a / b) is Python's a // b when b is an int (up to a quotient within an
        // ulp of an integer); with a float divisor (1 // 0.1 is 9) Python's own
        // algorithm, which repeats the operands: only when short and not random.
        if (b != T::Int && repeatable && l.text.size() + r.text.size() <= 80) {
            const Out rest = binaryText(l, "-", binaryText(l, "%", r, kMul, T::Float), kAdd, T::Float);
            return {"round(" + binaryText(rest, "/", r, kMul, T::Float).text + ")", T::Int, kPrimary};
        }
        return {"floor(" + binaryText(l, "/", r, kMul, T::Float).text + ")", T::Int, kPrimary};
    }
    if (op == "%") {
        // g2d's `%` is floored like Python's: the result has the divisor's sign (§10.2).
        if (isNum(a) && isNum(b)) return binaryText(l, op, r, kMul, numResult(a, b));
        if (a == T::String) fail(column, "printf-style `%` formatting is not supported; use an f-string");
        bad("");
    }
    if (op == "**") {
        if (isNum(a) && isNum(b)) return call("pow", {l, r}, T::Float);
        bad("");
    }
    fail(column, "the operator `" + op + "` is not supported");
}

Out Translator::boolOp(const Node& n) {
    const Out l = expr(*n.kids[0]);
    const Out r = expr(*n.kids[1]);
    for (const Out* o : {&l, &r})
        if (o->type != T::Bool && o->type != T::Unknown)
            fail(n.column, "`" + n.text + "` takes bools in g2d, got " + name(o->type) +
                               "; compare explicitly (e.g. `x != 0`)");
    const int level = n.text == "and" ? kAnd : kOr;
    // `and` inside `or` is bracketed although g2d would not need it: easier to read.
    auto side = [&](const Out& o, bool right) { return wrapIf(o, o.level >= kNot && (right || o.level != level)); };
    return {side(l, false) + " " + n.text + " " + side(r, true), T::Bool, level};
}

Out Translator::comparison(const Out& l, const std::string& op, const Out& r, int column) {
    const T a = l.type, b = r.type;
    if (op == "in" || op == "not in") fail(column, "`" + op + "` is not supported");
    if (op == "is" || op == "is not") fail(column, "`" + op + "` is not supported; compare with `==` or `!=`");
    if (a == T::None || b == T::None) fail(column, "comparison with `None` is not supported");
    const bool equality = op == "==" || op == "!=";
    if (equality) {
        if (!(a == b || (isNum(a) && isNum(b)) || a == T::Unknown || b == T::Unknown))
            fail(column, "`" + op + "` cannot compare " + name(a) + " and " + name(b));
    } else {
        if (a == T::String || b == T::String) fail(column, "strings are not ordered in g2d");
        if (!isNum(a) || !isNum(b)) fail(column, "`" + op + "` needs numbers, got " + name(a) + " and " + name(b));
    }
    return {below(l, kRel) + " " + op + " " + below(r, kRel), T::Bool, equality ? kEq : kRel};
}

Out Translator::compare(const Node& n) {
    std::vector<Out> operands;
    for (const py::NodePtr& k : n.kids) operands.push_back(expr(*k));
    if (n.ops.size() == 1) return comparison(operands[0], n.ops[0], operands[1], n.opColumns[0]);
    std::string text;
    for (std::size_t i = 0; i < n.ops.size(); ++i)
        text += (i ? " and (" : "(") + comparison(operands[i], n.ops[i], operands[i + 1], n.opColumns[i]).text + ")";
    return {text, T::Bool, kAnd};
}

Out Translator::conditional(const Node& n) {
    const Out body = expr(*n.kids[0]);
    const Out cond = truth(expr(*n.kids[1]), startColumn(*n.kids[1]));
    const Out other = expr(*n.kids[2]);
    const std::optional<T> type = unify(body.type, other.type);
    if (!type)
        fail(n.column, "the branches of `if`-`else` have different types: " + name(body.type) + " and " + name(other.type));
    return {"(" + cond.text + " ? " + body.text + " : " + other.text + ")", *type, kPrimary};
}

Out Translator::fstring(const Node& n) {
    std::string templ, plain;
    std::vector<Out> args(1);
    for (const py::FPart& p : n.parts) {
        if (p.expr < 0) {
            templ += escapeString(p.literal, true);
            plain += escapeString(p.literal, false);
            continue;
        }
        const Node& e = *n.kids[static_cast<std::size_t>(p.expr)];
        Out v = expr(e);
        // Bools print True/False in Python, true/false in g2d: accepted as a cosmetic difference.
        if (v.type == T::Vec2)
            fail(startColumn(e), "a vector in an f-string prints differently in g2d; format its `.x` and `.y`");
        if (v.type == T::None) fail(startColumn(e), "`None` has no g2d value");
        if (p.spec.empty()) {
            templ += "{}";
        } else {
            const std::string& s = p.spec;
            const bool fixed = s.size() >= 3 && s.size() <= 4 && s[0] == '.' && s.back() == 'f' &&
                               s.find_first_not_of("0123456789", 1) == s.size() - 1;
            if (!fixed || std::stoi(s.substr(1)) > 17)
                fail(p.specColumn, "the format spec `:" + s + "` is not supported; g2d knows `{:.N}` (N = 0…17 decimals, Python's `:.Nf`)");
            if (!isNum(v.type)) fail(p.specColumn, "the format spec `:" + s + "` needs a number, got " + name(v.type));
            templ += "{:" + s.substr(0, s.size() - 1) + "}";
        }
        args.push_back(std::move(v));
    }
    if (args.size() == 1) return {"\"" + plain + "\"", T::String, kPrimary};
    args[0] = {"\"" + templ + "\"", T::String, kPrimary};
    return call("format", args, T::String);
}

}  // namespace g2d::import::translation

namespace g2d::import {
namespace {

using translation::Fail;
using translation::Out;
using translation::Translator;

// One line, whatever the quoted source held (a key may contain an escaped newline).
std::string oneLine(const std::string& problem) {
    std::string out;
    for (char c : problem) out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    return out;
}

}  // namespace

namespace {

// One Python name, and nothing else (the whole value of an older file's `label: a_r`).
std::string_view trimmed(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

bool oneName(std::string_view s) {
    s = trimmed(s);
    if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
    for (char c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
    return true;
}

PyTranslation translateExpression(std::string_view source, const PyContext& context);

}  // namespace

// The tool's older files wrote strings bare (`label: a_r`, `.svg_tag: rect`)
// and compared and stored them as the text they are; later versions read
// every value as Python. A whole value that is one name the grammar does not
// know is read the old way: the text, and in a condition, `attr == 'text'`.
PyTranslation translatePython(std::string_view source, const PyContext& context) {
    PyTranslation result = translateExpression(source, context);
    if (result.ok || !oneName(source) || result.problem.rfind("unknown name", 0) != 0) return result;
    // A bare word is the tool's older string value (`label: a_r`): compared as a string.
    const std::string_view word = trimmed(source);
    const std::string quoted = "'" + std::string(word) + "'";
    PyTranslation asString = translateExpression(context.conditionElement.empty() ? quoted : "attr == " + quoted, context);
    if (!asString.ok) asString.column = static_cast<int>(word.data() - source.data());   // a column of the source, not of the rewrite
    return asString;
}

namespace {

PyTranslation translateExpression(std::string_view source, const PyContext& context) {
    PyTranslation result;
    try {
        py::ParseResult parsed = py::parsePython(source);
        if (!parsed.root) {
            result.problem = oneLine(parsed.problem);
            result.column = parsed.column;
            return result;
        }
        Out out = Translator(context).expr(*parsed.root);
        result.ok = true;
        result.text = std::move(out.text);
        result.type = out.type;
    } catch (const Fail& f) {
        result = {};
        result.problem = oneLine(f.problem);
        result.column = f.column;
    } catch (const std::exception& e) {
        result = {};
        result.problem = std::string("the expression could not be translated: ") + e.what();
    } catch (...) {
        result = {};
        result.problem = "the expression could not be translated";
    }
    return result;
}

}  // namespace

std::string_view pyTypeName(PyType type) {
    switch (type) {
        case PyType::Unknown: return "unknown";
        case PyType::Bool: return "bool";
        case PyType::Int: return "int";
        case PyType::Float: return "float";
        case PyType::String: return "string";
        case PyType::Vec2: return "vec2";
        case PyType::None: return "none";
    }
    return "unknown";
}

}  // namespace g2d::import
