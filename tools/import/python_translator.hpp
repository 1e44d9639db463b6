#pragma once
// The translator of python_expr.cpp, shared by its two halves: python_expr.cpp
// (names, attributes, operators, f-strings) and python_calls.cpp (calls of
// Python's and the tool's functions). Internal to the importer.
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "import/model_gen_names.hpp"
#include "import/python_expr.hpp"
#include "import/python_parse.hpp"

namespace g2d::import::translation {

using py::Node;
using K = Node::Kind;

struct Fail {
    std::string problem;
    int column;
};
[[noreturn]] inline void fail(int column, std::string problem) { throw Fail{std::move(problem), column}; }

// g2d's precedence levels (§10.1); a smaller level binds tighter.
enum Level { kPrimary = 1, kMember, kPrefix, kMul, kAdd, kRel, kEq, kNot, kAnd, kOr, kCond };

struct Out {
    std::string text;
    PyType type = PyType::Unknown;
    int level = kPrimary;
};

inline std::string name(PyType t) { return std::string(pyTypeName(t)); }
// Unknown operands pass: the caller could not type them, g2d's checker will.
inline bool isNum(PyType t) { return t == PyType::Int || t == PyType::Float || t == PyType::Unknown; }
inline bool isVec(PyType t) { return t == PyType::Vec2 || t == PyType::Unknown; }

inline PyType numResult(PyType a, PyType b) {
    if (a == PyType::Float || b == PyType::Float) return PyType::Float;
    if (a == PyType::Int && b == PyType::Int) return PyType::Int;
    return PyType::Unknown;
}

inline std::string wrapIf(const Out& o, bool wrap) { return wrap ? "(" + o.text + ")" : o.text; }
inline std::string atMost(const Out& o, int level) { return wrapIf(o, o.level > level); }
inline std::string below(const Out& o, int level) { return wrapIf(o, o.level >= level); }

// A left-associative g2d operator at `level`.
inline Out binaryText(const Out& l, std::string_view op, const Out& r, int level, PyType type) {
    return {atMost(l, level) + " " + std::string(op) + " " + below(r, level), type, level};
}
inline Out call(std::string_view fn, const std::vector<Out>& args, PyType type) {
    std::string text = std::string(fn) + "(";
    for (std::size_t i = 0; i < args.size(); ++i) text += (i ? ", " : "") + args[i].text;
    return {text + ")", type, kPrimary};
}



// The level of a caller's text: a name, `a.b`, a call or a bracketed whole is
// tight; anything else is wrapped wherever it is an operand.
inline int levelOf(std::string_view text) {
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

inline std::string dotted(const Node& n) { return n.kind == K::Attr ? dotted(*n.kids[0]) + "." + n.text : n.text; }

inline int startColumn(const Node& n) {
    switch (n.kind) {
        case K::Attr: case K::Subscript: case K::Call: case K::Binary: case K::BoolOp: case K::Compare: case K::IfExp:
            return startColumn(*n.kids[0]);
        default: return n.column;
    }
}

// Python's and the tool's callables (productions.py's namespace, §7 of the
// format notes; `math`/`np`/`random` members through numericFunction).
inline const std::set<std::string_view> kFunctions = {
    "abs", "min", "max", "round", "pow", "int", "float", "str", "bool", "sqrt", "asin", "acos", "atan",
    "isnan", "isinf", "Vec", "norm", "normalize", "cross", "perp_left", "perp_right", "angle", "rotate"};
inline const std::set<std::string_view> kModules = {"math", "np", "numpy", "random", "scipy"};

// A numeric function: name in g2d, arity, and result (Same: int if all args are int).
struct NumFn {
    std::string_view g2d;
    int minArgs, maxArgs;
    enum Result { F, I, Same } result;
};
// Python's `function` of `module` ("" for a builtin), if g2d has it (python_calls.cpp).
std::optional<NumFn> numericFunction(std::string_view module, std::string_view function);

// What a bare name stands for.
struct Ref {
    enum class Kind { Value, Element, Placed, Module, Function, Attr, Attrs };
    Kind kind;
    PyBinding binding;
};

// Python's `x if c else y` and random.choice's elements: one type, ints and floats mix.
inline std::optional<PyType> unify(PyType a, PyType b) {
    if (a == PyType::None || b == PyType::None) return std::nullopt;
    if (isNum(a) && isNum(b)) return numResult(a, b);
    if (a == b || b == PyType::Unknown) return a;
    if (a == PyType::Unknown) return b;
    return std::nullopt;
}

class Translator {
public:
    explicit Translator(const PyContext& context) : c_(context) {}

    Out expr(const Node& n);

private:
    using T = PyType;

    Out bare(const Node& n);

    // Whether the tree calls random.*: such an operand must not be written twice.
    bool random(const Node& n);

    std::optional<Ref> resolve(const std::string& name);

    Out nameValue(const Node& n);

    // `elem.key` in g2d; x and y are the node's position (the fact `pos`, §13).
    Out attributeRead(const std::string& elem, bool isNode, const std::string& key, int column);

    Out attribute(const Node& n);

    Out moduleConstant(const std::string& module, const std::string& a, int column);

    Out subscript(const Node& n);

    Out unary(const Node& n);

    // Python's `not`: truthiness of numbers and strings spelled out (g2d's `!` takes bools).
    Out negate(const Out& v, int column);
    Out truth(const Out& v, int column);

    Out arithmetic(const std::string& op, const Out& l, const Out& r, int column, bool repeatable = false);

    Out boolOp(const Node& n);

    Out comparison(const Out& l, const std::string& op, const Out& r, int column);

    // g2d's comparisons do not chain: a < b < c is (a < b) and (b < c).
    Out compare(const Node& n);

    Out conditional(const Node& n);

    // f'…{x}…{y:.2f}' → format("…{}…{:.2}", x, y) (§10.5).
    Out fstring(const Node& n);

    Out callExpr(const Node& n);

    Out arg(const Node& n, std::size_t i);
    Out numberArg(const Node& n, std::size_t i, const std::string& fn);
    Out vectorArg(const Node& n, std::size_t i, const std::string& fn);
    static void arity(const Node& n, std::size_t lo, std::size_t hi, const std::string& fn, int column);

    Out function(const std::string& module, const std::string& fn, const Node& n, int column);

    Out conversion(const std::string& fn, const Node& n, int column);

    // Vec(v) position of a node; Vec(a, b) = b - a; Vec(x1, y1, x2, y2); keywords (geometry.py).
    Out position(const Node& a);
    Out number(const Node& a, const std::string& what);
    Out difference(const Out& from, const Out& to);
    Out vecLiteral(const Node* x1, const Node* y1, const Node* x2, const Node* y2);

    Out vecCall(const Node& n, int column);

    // random.choice((a, b, …)) → choice(a, b, …): the choices must be written inline.
    Out choice(const Node& n, int column);

    const PyContext& c_;
};

}  // namespace g2d::import::translation
