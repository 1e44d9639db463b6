// Calls in the tool's Python: its library (Vec, norm, rotate, …), math, numpy
// and random functions, and conversions, as g2d built-ins.
#include "import/python_translator.hpp"

namespace g2d::import::translation {

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

Out Translator::callExpr(const Node& n) {
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

Out Translator::arg(const Node& n, std::size_t i) { return expr(*n.kids[i + 1]); }

Out Translator::numberArg(const Node& n, std::size_t i, const std::string& fn) {
    Out v = arg(n, i);
    if (!isNum(v.type))
        fail(startColumn(*n.kids[i + 1]), "argument " + std::to_string(i + 1) + " of `" + fn + "` must be a number, got " + name(v.type));
    return v;
}

Out Translator::vectorArg(const Node& n, std::size_t i, const std::string& fn) {
    Out v = arg(n, i);
    if (!isVec(v.type))
        fail(startColumn(*n.kids[i + 1]), "argument " + std::to_string(i + 1) + " of `" + fn + "` must be a vector, got " + name(v.type));
    return v;
}

void Translator::arity(const Node& n, std::size_t lo, std::size_t hi, const std::string& fn, int column) {
    const std::size_t argc = n.kids.size() - 1;
    if (argc >= lo && argc <= hi) return;
    const std::string want = lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi);
    fail(column, "`" + fn + "` takes " + want + " argument" + (want == "1" ? "" : "s") + ", got " + std::to_string(argc));
}

Out Translator::function(const std::string& module, const std::string& fn, const Node& n, int column) {
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

Out Translator::conversion(const std::string& fn, const Node& n, int column) {
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

Out Translator::position(const Node& a) {
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

Out Translator::number(const Node& a, const std::string& what) {
    Out v = expr(a);
    if (!isNum(v.type)) fail(startColumn(a), "`" + what + "` of `Vec` must be a number, got " + name(v.type));
    return v;
}

Out Translator::difference(const Out& from, const Out& to) { return {"(" + binaryText(to, "-", from, kAdd, T::Vec2).text + ")", T::Vec2, kPrimary}; }

Out Translator::vecLiteral(const Node* x1, const Node* y1, const Node* x2, const Node* y2) {
    Out x = number(*x1, "x1"), y = number(*y1, "y1");
    if (x2) {
        x = binaryText(number(*x2, "x2"), "-", x, kAdd, T::Float);
        y = binaryText(number(*y2, "y2"), "-", y, kAdd, T::Float);
    }
    return {"(" + x.text + ", " + y.text + ")", T::Vec2, kPrimary};
}

Out Translator::vecCall(const Node& n, int column) {
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

Out Translator::choice(const Node& n, int column) {
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

}  // namespace g2d::import::translation
