// Python (model_gen) expressions to g2d expressions: python_parse.cpp builds the
// tree, this file types it and writes the g2d text (docs/language.md §10, §13).
#include "import/python_expr.hpp"

#include <cctype>
#include <exception>
#include <set>
#include <utility>

#include "import/model_gen_names.hpp"
#include "import/model_gen_styles.hpp"
#include "import/python_parse.hpp"

namespace g2d::import {
namespace {

using py::Node;
using K = Node::Kind;

struct Fail {
    std::string problem;
    int column;
};
[[noreturn]] void fail(int column, std::string problem) { throw Fail{std::move(problem), column}; }

// g2d's precedence levels (§10.1); a smaller level binds tighter.
enum Level { kPrimary = 1, kMember, kPrefix, kMul, kAdd, kRel, kEq, kNot, kAnd, kOr, kCond };

struct Out {
    std::string text;
    PyType type = PyType::Unknown;
    int level = kPrimary;
};

std::string name(PyType t) { return std::string(pyTypeName(t)); }
// Unknown operands pass: the caller could not type them, g2d's checker will.
bool isNum(PyType t) { return t == PyType::Int || t == PyType::Float || t == PyType::Unknown; }
bool isVec(PyType t) { return t == PyType::Vec2 || t == PyType::Unknown; }

PyType numResult(PyType a, PyType b) {
    if (a == PyType::Float || b == PyType::Float) return PyType::Float;
    if (a == PyType::Int && b == PyType::Int) return PyType::Int;
    return PyType::Unknown;
}

std::string wrapIf(const Out& o, bool wrap) { return wrap ? "(" + o.text + ")" : o.text; }
std::string atMost(const Out& o, int level) { return wrapIf(o, o.level > level); }
std::string below(const Out& o, int level) { return wrapIf(o, o.level >= level); }

// A left-associative g2d operator at `level`.
Out binaryText(const Out& l, std::string_view op, const Out& r, int level, PyType type) {
    return {atMost(l, level) + " " + std::string(op) + " " + below(r, level), type, level};
}
Out call(std::string_view fn, const std::vector<Out>& args, PyType type) {
    std::string text = std::string(fn) + "(";
    for (std::size_t i = 0; i < args.size(); ++i) text += (i ? ", " : "") + args[i].text;
    return {text + ")", type, kPrimary};
}



// The level of a caller's text: a name, `a.b`, a call or a bracketed whole is
// tight; anything else is wrapped wherever it is an operand.
int levelOf(std::string_view text) {
    int depth = 0;
    bool member = false;
    char quote = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quote) {
            if (c == '\\') ++i;
            else if (c == quote) quote = 0;
        } else if (c == '"') {
            quote = c;
        } else if (c == '(') {
            ++depth;
        } else if (c == ')') {
            if (--depth < 0) return kCond;
        } else if (depth == 0) {
            if (c == '.') member = true;
            else if (!isIdentifier(std::string_view(&c, 1)) && !(c >= '0' && c <= '9')) return kCond;
        }
    }
    return depth == 0 && !quote ? (member ? kMember : kPrimary) : kCond;
}

std::string dotted(const Node& n) { return n.kind == K::Attr ? dotted(*n.kids[0]) + "." + n.text : n.text; }

int startColumn(const Node& n) {
    switch (n.kind) {
        case K::Attr: case K::Subscript: case K::Call: case K::Binary: case K::BoolOp: case K::Compare: case K::IfExp:
            return startColumn(*n.kids[0]);
        default: return n.column;
    }
}

// Python's and the tool's callables (productions.py's namespace, §7 of the
// format notes; `math`/`np`/`random` members through numericFunction).
const std::set<std::string_view> kFunctions = {
    "abs", "min", "max", "round", "pow", "int", "float", "str", "bool", "sqrt", "asin", "acos", "atan",
    "isnan", "isinf", "Vec", "norm", "normalize", "cross", "perp_left", "perp_right", "angle", "rotate"};
const std::set<std::string_view> kModules = {"math", "np", "numpy", "random", "scipy"};

// A numeric function: name in g2d, arity, and result (Same: int if all args are int).
struct NumFn {
    std::string_view g2d;
    int minArgs, maxArgs;
    enum Result { F, I, Same } result;
};

std::optional<NumFn> numericFunction(std::string_view module, std::string_view function) {
    using R = NumFn::Result;
    static const std::vector<std::pair<std::string_view, NumFn>> kBare = {
        {"sqrt", {"sqrt", 1, 1, R::F}}, {"asin", {"asin", 1, 1, R::F}}, {"acos", {"acos", 1, 1, R::F}},
        {"atan", {"atan", 1, 1, R::F}}, {"abs", {"abs", 1, 1, R::Same}}, {"pow", {"pow", 2, 2, R::F}},
        // Python rounds halves to even, g2d away from zero (§10.4): only exact .5 differ.
        {"round", {"round", 1, 1, R::I}}, {"min", {"min", 2, 1 << 20, R::Same}}, {"max", {"max", 2, 1 << 20, R::Same}}};
    static const std::vector<std::pair<std::string_view, NumFn>> kMath = {
        {"sin", {"sin", 1, 1, R::F}}, {"cos", {"cos", 1, 1, R::F}}, {"tan", {"tan", 1, 1, R::F}},
        {"asin", {"asin", 1, 1, R::F}}, {"acos", {"acos", 1, 1, R::F}}, {"atan", {"atan", 1, 1, R::F}},
        {"atan2", {"atan2", 2, 2, R::F}}, {"sqrt", {"sqrt", 1, 1, R::F}}, {"exp", {"exp", 1, 1, R::F}},
        {"log", {"log", 1, 1, R::F}}, {"hypot", {"hypot", 2, 2, R::F}}, {"pow", {"pow", 2, 2, R::F}},
        {"floor", {"floor", 1, 1, R::I}}, {"ceil", {"ceil", 1, 1, R::I}}, {"fabs", {"abs", 1, 1, R::F}},
        {"radians", {"radians", 1, 1, R::F}}, {"degrees", {"degrees", 1, 1, R::F}}};
    static const std::vector<std::pair<std::string_view, NumFn>> kNumpy = {
        {"sin", {"sin", 1, 1, R::F}}, {"cos", {"cos", 1, 1, R::F}}, {"tan", {"tan", 1, 1, R::F}},
        {"arcsin", {"asin", 1, 1, R::F}}, {"arccos", {"acos", 1, 1, R::F}}, {"arctan", {"atan", 1, 1, R::F}},
        {"arctan2", {"atan2", 2, 2, R::F}}, {"sqrt", {"sqrt", 1, 1, R::F}}, {"exp", {"exp", 1, 1, R::F}},
        {"log", {"log", 1, 1, R::F}}, {"hypot", {"hypot", 2, 2, R::F}}, {"power", {"pow", 2, 2, R::F}},
        {"floor", {"floor", 1, 1, R::I}}, {"ceil", {"ceil", 1, 1, R::I}}, {"round", {"round", 1, 1, R::I}},
        {"abs", {"abs", 1, 1, R::Same}}, {"absolute", {"abs", 1, 1, R::Same}}, {"sign", {"sign", 1, 1, R::Same}},
        {"deg2rad", {"radians", 1, 1, R::F}}, {"radians", {"radians", 1, 1, R::F}},
        {"rad2deg", {"degrees", 1, 1, R::F}}, {"degrees", {"degrees", 1, 1, R::F}},
        {"minimum", {"min", 2, 2, R::Same}}, {"maximum", {"max", 2, 2, R::Same}}};
    static const std::vector<std::pair<std::string_view, NumFn>> kRandom = {
        {"random", {"random", 0, 0, R::F}}, {"uniform", {"uniform", 2, 2, R::F}},
        {"randint", {"randint", 2, 2, R::I}}, {"gauss", {"normal", 2, 2, R::F}},
        {"normalvariate", {"normal", 2, 2, R::F}}};
    const auto& table = module.empty() ? kBare : module == "math" ? kMath : module == "random" ? kRandom
                        : (module == "np" || module == "numpy") ? kNumpy : kBare;
    if (module == "scipy") return std::nullopt;
    for (const auto& [py, fn] : table)
        if (py == function) return fn;
    return std::nullopt;
}

// What a bare name stands for.
struct Ref {
    enum class Kind { Value, Element, Placed, Module, Function, Attr, Attrs };
    Kind kind;
    PyBinding binding;
};

// Python's `x if c else y` and random.choice's elements: one type, ints and floats mix.
std::optional<PyType> unify(PyType a, PyType b) {
    if (a == PyType::None || b == PyType::None) return std::nullopt;
    if (isNum(a) && isNum(b)) return numResult(a, b);
    if (a == b || b == PyType::Unknown) return a;
    if (a == PyType::Unknown) return b;
    return std::nullopt;
}

class Translator {
public:
    explicit Translator(const PyContext& context) : c_(context) {}

    Out expr(const Node& n) {
        Out o = bare(n);
        if (n.parenthesized && o.level > kPrimary) o = {"(" + o.text + ")", o.type, kPrimary};
        return o;
    }

private:
    using T = PyType;

    Out bare(const Node& n) {
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

    // Whether the tree calls random.*: such an operand must not be written twice.
    bool random(const Node& n) {
        if (n.kind == K::Call && n.kids[0]->kind == K::Attr && n.kids[0]->kids[0]->kind == K::Name &&
            n.kids[0]->kids[0]->text == "random")
            return true;
        for (const py::NodePtr& k : n.kids)
            if (random(*k)) return true;
        return false;
    }

    std::optional<Ref> resolve(const std::string& name) {
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

    Out nameValue(const Node& n) {
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

    // `elem.key` in g2d; x and y are the node's position (the fact `pos`, §13).
    Out attributeRead(const std::string& elem, bool isNode, const std::string& key, int column) {
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

    Out attribute(const Node& n) {
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

    Out moduleConstant(const std::string& module, const std::string& a, int column) {
        if (module == "math" || module == "np" || module == "numpy") {
            if (a == "pi") return {"pi", T::Float, kPrimary};
            if (a == "tau") return {"tau", T::Float, kPrimary};
            if (a == "e") return {"exp(1.0)", T::Float, kPrimary};
        }
        if (numericFunction(module, a) || (module == "random" && a == "choice"))
            fail(column, "`" + module + "." + a + "` is a function; call it");
        fail(column, "`" + module + "." + a + "` has no g2d counterpart");
    }

    Out subscript(const Node& n) {
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

    Out unary(const Node& n) {
        const Out v = expr(*n.kids[0]);
        if (n.text == "~") fail(n.column, "the bitwise operator `~` is not supported");
        if (!isNum(v.type) && v.type != T::Vec2)
            fail(n.column, "unary `" + n.text + "` needs a number or a vector, got " + name(v.type));
        if (n.text == "+") return v;
        return {"-" + atMost(v, kMember), v.type, kPrefix};
    }

    // Python's `not`: truthiness of numbers and strings spelled out (g2d's `!` takes bools).
    Out negate(const Out& v, int column) {
        switch (v.type) {
            // Unknown: taken as bool, the tool's grammars apply `not` to flags.
            case T::Bool: case T::Unknown: return {"!" + atMost(v, kMember), T::Bool, kPrefix};
            case T::Int: case T::Float: return {below(v, kRel) + " == 0", T::Bool, kEq};
            case T::String: return {below(v, kRel) + " == \"\"", T::Bool, kEq};
            default: fail(column, "`not` of a " + name(v.type) + " has no g2d counterpart");
        }
    }
    Out truth(const Out& v, int column) {
        switch (v.type) {
            case T::Bool: case T::Unknown: return v;
            case T::Int: case T::Float: return {below(v, kRel) + " != 0", T::Bool, kEq};
            case T::String: return {below(v, kRel) + " != \"\"", T::Bool, kEq};
            default: fail(column, "the truth of a " + name(v.type) + " has no g2d counterpart");
        }
    }

    Out arithmetic(const std::string& op, const Out& l, const Out& r, int column, bool repeatable = false) {
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

    Out boolOp(const Node& n) {
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

    Out comparison(const Out& l, const std::string& op, const Out& r, int column) {
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

    // g2d's comparisons do not chain: a < b < c is (a < b) and (b < c).
    Out compare(const Node& n) {
        std::vector<Out> operands;
        for (const py::NodePtr& k : n.kids) operands.push_back(expr(*k));
        if (n.ops.size() == 1) return comparison(operands[0], n.ops[0], operands[1], n.opColumns[0]);
        std::string text;
        for (std::size_t i = 0; i < n.ops.size(); ++i)
            text += (i ? " and (" : "(") + comparison(operands[i], n.ops[i], operands[i + 1], n.opColumns[i]).text + ")";
        return {text, T::Bool, kAnd};
    }

    Out conditional(const Node& n) {
        const Out body = expr(*n.kids[0]);
        const Out cond = truth(expr(*n.kids[1]), startColumn(*n.kids[1]));
        const Out other = expr(*n.kids[2]);
        const std::optional<T> type = unify(body.type, other.type);
        if (!type)
            fail(n.column, "the branches of `if`-`else` have different types: " + name(body.type) + " and " + name(other.type));
        return {"(" + cond.text + " ? " + body.text + " : " + other.text + ")", *type, kPrimary};
    }

    // f'…{x}…{y:.2f}' → format("…{}…{:.2}", x, y) (§10.5).
    Out fstring(const Node& n) {
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

    Out callExpr(const Node& n) {
        const Node& callee = *n.kids[0];
        if (callee.kind == K::Name) {
            const std::optional<Ref> r = resolve(callee.text);
            if (!r && numericFunction("math", callee.text))
                fail(callee.column, "unknown function `" + callee.text + "`; write `np." +
                                        (callee.text == "atan2" ? "arctan2" : callee.text) + "(…)`");
            if (!r) fail(callee.column, "unknown function `" + callee.text + "`");
            if (r->kind == Ref::Kind::Function) return function("", callee.text, n, callee.column);
            fail(callee.column, "`" + callee.text + "` is not a function");
        }
        if (callee.kind == K::Attr && callee.kids[0]->kind == K::Name) {
            const Node& module = *callee.kids[0];
            const std::optional<Ref> r = resolve(module.text);
            if (r && r->kind == Ref::Kind::Module) return function(module.text, callee.text, n, module.column);
        }
        if (callee.kind == K::Attr) {
            // scipy.stats.norm(…): a module's member, not a method.
            const Node* root = &callee;
            while (root->kind == K::Attr) root = root->kids[0].get();
            const std::optional<Ref> r = root->kind == K::Name ? resolve(root->text) : std::nullopt;
            if (r && r->kind == Ref::Kind::Module) fail(root->column, "`" + dotted(callee) + "` has no g2d counterpart");
            fail(callee.column, "method calls (`." + callee.text + "(…)`) are not supported");
        }
        fail(n.column, "only calls of known functions are supported");
    }

    Out arg(const Node& n, std::size_t i) { return expr(*n.kids[i + 1]); }
    Out numberArg(const Node& n, std::size_t i, const std::string& fn) {
        Out v = arg(n, i);
        if (!isNum(v.type))
            fail(startColumn(*n.kids[i + 1]), "argument " + std::to_string(i + 1) + " of `" + fn + "` must be a number, got " + name(v.type));
        return v;
    }
    Out vectorArg(const Node& n, std::size_t i, const std::string& fn) {
        Out v = arg(n, i);
        if (!isVec(v.type))
            fail(startColumn(*n.kids[i + 1]), "argument " + std::to_string(i + 1) + " of `" + fn + "` must be a vector, got " + name(v.type));
        return v;
    }
    static void arity(const Node& n, std::size_t lo, std::size_t hi, const std::string& fn, int column) {
        const std::size_t argc = n.kids.size() - 1;
        if (argc >= lo && argc <= hi) return;
        const std::string want = lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi);
        fail(column, "`" + fn + "` takes " + want + " argument" + (want == "1" ? "" : "s") + ", got " + std::to_string(argc));
    }

    Out function(const std::string& module, const std::string& fn, const Node& n, int column) {
        const std::string display = module.empty() ? fn : module + "." + fn;
        const bool vec = module.empty() && fn == "Vec";
        for (std::size_t i = 0; i < n.keywords.size(); ++i)
            if (!vec && !n.keywords[i].empty())
                fail(n.kids[i + 1]->column, "keyword arguments are supported only in `Vec(…)`");
        if (fn == "isnan" || fn == "isinf") fail(column, "`" + display + "` has no g2d counterpart");
        if (module == "scipy") fail(column, "`scipy` has no g2d counterpart");
        if (module.empty()) {
            if (vec) return vecCall(n, column);
            if (fn == "int" || fn == "float" || fn == "str" || fn == "bool") return conversion(fn, n, column);
            if (fn == "norm" || fn == "normalize" || fn == "perp_left" || fn == "perp_right") {
                arity(n, 1, 1, fn, column);
                const Out v = vectorArg(n, 0, fn);
                return fn == "norm" ? call("length", {v}, T::Float) : call(fn, {v}, T::Vec2);
            }
            if (fn == "cross" || fn == "angle") {
                arity(n, 2, 2, fn, column);
                const Out c = call(fn, {vectorArg(n, 0, fn), vectorArg(n, 1, fn)}, T::Float);
                // The tool's angle is acos of the cosine (unsigned); g2d's is signed (§13).
                return fn == "angle" ? call("abs", {c}, T::Float) : c;
            }
            if (fn == "rotate") {
                arity(n, 2, 3, fn, column);
                std::vector<Out> args = {vectorArg(n, 0, fn), numberArg(n, 1, fn)};
                if (n.kids.size() == 4) args.push_back(vectorArg(n, 2, fn));
                return call("rotate", args, T::Vec2);
            }
        }
        if (module == "random" && fn == "choice") return choice(n, column);
        const std::optional<NumFn> f = numericFunction(module, fn);
        if (!f) fail(column, "`" + display + "` has no g2d counterpart");
        std::vector<const Node*> argNodes;
        for (std::size_t i = 1; i < n.kids.size(); ++i) argNodes.push_back(n.kids[i].get());
        // min((a, b)) and max([a, b]) take their elements.
        if ((f->g2d == "min" || f->g2d == "max") && argNodes.size() == 1 &&
            (argNodes[0]->kind == K::Tuple || argNodes[0]->kind == K::List)) {
            const Node* seq = argNodes[0];
            argNodes.clear();
            for (const py::NodePtr& k : seq->kids) argNodes.push_back(k.get());
        }
        if (argNodes.size() < static_cast<std::size_t>(f->minArgs) || argNodes.size() > static_cast<std::size_t>(f->maxArgs)) {
            const std::string want = f->minArgs == f->maxArgs ? std::to_string(f->minArgs) : std::to_string(f->minArgs) + " or more";
            fail(column, "`" + display + "` takes " + want + " argument" + (want == "1" ? "" : "s") + ", got " + std::to_string(argNodes.size()));
        }
        std::vector<Out> args;
        T same = T::Int;
        for (std::size_t i = 0; i < argNodes.size(); ++i) {
            Out v = expr(*argNodes[i]);
            const bool ok = fn == "randint" ? (v.type == T::Int || v.type == T::Unknown) : isNum(v.type);
            if (!ok)
                fail(startColumn(*argNodes[i]), "argument " + std::to_string(i + 1) + " of `" + display + "` must be " +
                                                    (fn == "randint" ? "an int" : "a number") + ", got " + name(v.type));
            same = i == 0 ? v.type : numResult(same, v.type);
            args.push_back(std::move(v));
        }
        const T result = f->result == NumFn::F ? T::Float : f->result == NumFn::I ? T::Int : same;
        return call(f->g2d, args, result);
    }

    Out conversion(const std::string& fn, const Node& n, int column) {
        arity(n, 1, 1, fn, column);
        const Out v = arg(n, 0);
        const int at = startColumn(*n.kids[1]);
        if (v.type == T::None || v.type == T::Vec2) fail(at, "`" + fn + "` of a " + name(v.type) + " has no g2d counterpart");
        if (fn == "bool") return truth(v, at);
        if (fn == "int") return v.type == T::Int ? v : call("int", {v}, T::Int);
        // A float parameter takes an int (§3), so float(n) of a number is n itself.
        if (fn == "float") return v.type == T::Int || v.type == T::Float ? Out{v.text, T::Float, v.level} : call("float", {v}, T::Float);
        // str(True) is "True" in Python, "true" in g2d: accepted as a cosmetic difference.
        return v.type == T::String ? v : call("str", {v}, T::String);
    }

    // Vec(v) position of a node; Vec(a, b) = b - a; Vec(x1, y1, x2, y2); keywords (geometry.py).
    Out position(const Node& a) {
        if (a.kind == K::Name) {
            const std::optional<Ref> r = resolve(a.text);
            if (r && r->kind == Ref::Kind::Placed) return {"placed", T::Vec2, kPrimary};
            if (r && r->kind == Ref::Kind::Element) {
                if (!r->binding.isNode) fail(a.column, "`" + a.text + "` is an edge, which has no position");
                return {r->binding.text + ".pos", T::Vec2, kMember};
            }
        }
        fail(startColumn(a), "`Vec(v)` needs a matched node or `self_`; for a vector value write `Vec(vec1=v)`");
    }
    Out number(const Node& a, const std::string& what) {
        Out v = expr(a);
        if (!isNum(v.type)) fail(startColumn(a), "`" + what + "` of `Vec` must be a number, got " + name(v.type));
        return v;
    }
    Out difference(const Out& from, const Out& to) { return {"(" + binaryText(to, "-", from, kAdd, T::Vec2).text + ")", T::Vec2, kPrimary}; }
    Out vecLiteral(const Node* x1, const Node* y1, const Node* x2, const Node* y2) {
        Out x = number(*x1, "x1"), y = number(*y1, "y1");
        if (x2) {
            x = binaryText(number(*x2, "x2"), "-", x, kAdd, T::Float);
            y = binaryText(number(*y2, "y2"), "-", y, kAdd, T::Float);
        }
        return {"(" + x.text + ", " + y.text + ")", T::Vec2, kPrimary};
    }

    Out vecCall(const Node& n, int column) {
        const std::size_t argc = n.kids.size() - 1;
        std::size_t positional = 0;
        for (const std::string& k : n.keywords) positional += k.empty();
        auto a = [&](std::size_t i) -> const Node& { return *n.kids[i + 1]; };
        if (positional == argc) {
            if (argc == 1) return position(a(0));
            if (argc == 2) {
                const Out from = position(a(0));
                return difference(from, position(a(1)));
            }
            if (argc == 4) return vecLiteral(&a(0), &a(1), &a(2), &a(3));
            fail(column, "`Vec` takes a node, two nodes, four numbers or keywords (x1=, y1= or vec1=, vec2=); got " +
                             std::to_string(argc) + " arguments");
        }
        if (positional > 0) fail(column, "`Vec` with both positional and keyword arguments is not supported");
        std::vector<std::pair<std::string, const Node*>> kw;
        for (std::size_t i = 0; i < argc; ++i) {
            for (const auto& [k, v] : kw)
                if (k == n.keywords[i]) fail(a(i).column, "the keyword `" + k + "` is given twice");
            kw.emplace_back(n.keywords[i], &a(i));
        }
        auto get = [&](std::string_view k) -> const Node* {
            for (const auto& [name, v] : kw)
                if (name == k) return v;
            return nullptr;
        };
        const Node *x1 = get("x1"), *y1 = get("y1"), *x2 = get("x2"), *y2 = get("y2"), *v1 = get("vec1"), *v2 = get("vec2");
        const std::size_t known = (x1 != nullptr) + (y1 != nullptr) + (x2 != nullptr) + (y2 != nullptr) + (v1 != nullptr) + (v2 != nullptr);
        if (known == argc && x1 && y1 && !v1 && !v2 && (x2 != nullptr) == (y2 != nullptr)) return vecLiteral(x1, y1, x2, y2);
        if (known == argc && v1 && !x1 && !y1 && !x2 && !y2) {
            auto vector = [&](const Node* node, const char* what) {
                Out v = expr(*node);
                if (!isVec(v.type)) fail(startColumn(*node), std::string("`") + what + "` of `Vec` must be a vector, got " + name(v.type));
                return v;
            };
            const Out from = vector(v1, "vec1");
            return v2 ? difference(from, vector(v2, "vec2")) : from;
        }
        fail(column, "`Vec` keywords must be x1, y1 (with x2, y2) or vec1 (with vec2)");
    }

    // random.choice((a, b, …)) → choice(a, b, …): the choices must be written inline.
    Out choice(const Node& n, int column) {
        if (n.kids.size() != 2 || (n.kids[1]->kind != K::Tuple && n.kids[1]->kind != K::List))
            fail(column, "`random.choice` needs its choices written inline, as in `random.choice((a, b))`");
        const Node& seq = *n.kids[1];
        if (seq.kids.empty()) fail(seq.column, "`random.choice` of an empty sequence");
        std::vector<Out> args;
        T type = T::Unknown;
        for (const py::NodePtr& k : seq.kids) {
            Out v = expr(*k);
            const std::optional<T> t = args.empty() ? std::optional<T>(v.type) : unify(type, v.type);
            if (!t || v.type == T::None)
                fail(startColumn(*k), "the choices of `random.choice` must have one type, got " + name(type) + " and " + name(v.type));
            type = *t;
            args.push_back(std::move(v));
        }
        if (args.size() == 1) return args[0];
        return call("choice", args, type);
    }

    const PyContext& c_;
};

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
