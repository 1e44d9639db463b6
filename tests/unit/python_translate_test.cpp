// g2d import: the Python expressions of model_gen grammars (every kind found in
// shared/reference/model_gen-examples/*.yml) rewritten as g2d expressions, and
// the problems reported for what g2d cannot express.
#include <catch2/catch.hpp>

#include <set>
#include <string>
#include <vector>

#include "import/python_expr.hpp"
#include "front/reserved_names.hpp"
#include "import/line_wrap.hpp"
#include "import/model_gen_names.hpp"
#include "sema/builtins.hpp"
#include "sema/element_facts.hpp"
#include "import/used_names.hpp"

using namespace g2d::import;

namespace {

PyBinding element(const char* name, bool isNode = true) {
    return {PyBinding::Kind::Element, name, PyType::Unknown, isNode};
}
PyBinding value(const char* text, PyType type) { return {PyBinding::Kind::Value, text, type, true}; }

// The names of a daughter of the tool's grammars: matched elements, vectors,
// variables, `self_`.
PyContext context() {
    PyContext c;
    c.lookup = [](std::string_view n) -> std::optional<PyBinding> {
        for (const char* node : {"arg0", "arg1", "old", "house", "h_floor", "v_floor", "center", "leave", "a", "b"})
            if (n == node) return element(node);
        for (const char* edge : {"trunk", "top_edge"})
            if (n == edge) return element(edge, false);
        for (const char* vec : {"A", "B", "C", "c", "s", "e", "v1", "v2"})
            if (n == vec) return value(vec, PyType::Vec2);
        for (const char* f : {"rot_deg", "width_decrease", "branch_contr", "fi"})
            if (n == f) return value(f, PyType::Float);
        for (const char* i : {"max_num_dots", "max_num_lines", "num_lines", "ii"})
            if (n == i) return value(i, PyType::Int);
        if (n == "si") return value("si", PyType::String);
        if (n == "bi") return value("bi", PyType::Bool);
        if (n == "mystery") return value("mystery", PyType::Unknown);
        if (n == "d") return value("b.pos - a.pos", PyType::Vec2);  // a compound text
        if (n == "self_") return PyBinding{PyBinding::Kind::Placed, "", PyType::Unknown, true};
        return std::nullopt;
    };
    c.attributeType = [](bool, std::string_view key) {
        for (const char* k : {"label", "direction"})
            if (key == k) return PyType::String;
        for (const char* k : {"num_leaves", "max_leaves", "floors", "floor", "number", "level", "num_dots"})
            if (key == k) return PyType::Int;
        if (key == "grown") return PyType::Bool;
        for (const char* k : {"length", "size", "width", "height", "blind_portion", "control_degree", "control_position"})
            if (key == k) return PyType::Float;
        return PyType::Unknown;
    };
    return c;
}

// A mother condition on the element `m` for its attribute `key`.
PyContext condition(const char* key) {
    PyContext c = context();
    c.conditionElement = "m";
    c.conditionKey = key;
    return c;
}

struct Case {
    const char* source;
    const char* text;
    PyType type;
};

void expectAll(const std::vector<Case>& cases, const PyContext& c = context()) {
    for (const Case& k : cases) {
        INFO(k.source);
        const PyTranslation r = translatePython(k.source, c);
        INFO(r.problem);
        REQUIRE(r.ok);
        CHECK(r.text == k.text);
        CHECK(std::string(pyTypeName(r.type)) == std::string(pyTypeName(k.type)));
    }
}

struct Failure {
    const char* source;
    const char* problem;
    int column;
};

void expectFailures(const std::vector<Failure>& cases, const PyContext& c = context()) {
    for (const Failure& k : cases) {
        INFO(k.source);
        const PyTranslation r = translatePython(k.source, c);
        INFO(r.text);
        CHECK_FALSE(r.ok);
        CHECK(r.problem == k.problem);
        CHECK(r.column == k.column);
    }
}

}  // namespace

TEST_CASE("python import translates literals", "[import]") {
    expectAll({
        {"0", "0", PyType::Int},
        {"10", "10", PyType::Int},
        {"1_000", "1000", PyType::Int},
        {"0x1F", "31", PyType::Int},
        {"0.5", "0.5", PyType::Float},
        {"1e-3", "1e-3", PyType::Float},
        {".5", ".5", PyType::Float},
        {"1.", "1.", PyType::Float},
        {"'Wall'", "\"Wall\"", PyType::String},
        {"\"Floor\"", "\"Floor\"", PyType::String},
        {"'#bbe5ff '", "\"#bbe5ff \"", PyType::String},
        {"'say \"hi\"\\\\'", "\"say \\\"hi\\\"\\\\\"", PyType::String},
        {"'a\\nb\\tc'", "\"a\\nb\\tc\"", PyType::String},
        {"'it''s' \"ok\"", "\"itsok\"", PyType::String},
        {"r'\\d'", "\"\\\\d\"", PyType::String},
        {"True", "true", PyType::Bool},
        {"False", "false", PyType::Bool},
        {"None", "none", PyType::None},
    });
    const PyTranslation nul = translatePython(std::string_view("'\0'", 3), context());
    CHECK(nul.ok);
    CHECK(nul.text == "\"\\0\"");
}

TEST_CASE("python import keeps Python's precedence and typing", "[import]") {
    expectAll({
        {"A + v1/2 + 1/3*(perp_left(v1))", "A + v1 / 2 + 1 / 3 * perp_left(v1)", PyType::Vec2},
        {"A + v1 * 2/3", "A + v1 * 2 / 3", PyType::Vec2},
        {"A + 0.5 * v1 / (max_num_lines - num_lines)", "A + 0.5 * v1 / (max_num_lines - num_lines)", PyType::Vec2},
        {"B + v1 * branch_contr", "B + v1 * branch_contr", PyType::Vec2},
        {"25 / 360 * pi", "25 / 360 * pi", PyType::Float},
        {"1/2", "1 / 2", PyType::Float},  // g2d's `/` divides as float, like Python 3's
        {"7 // 2", "floor(7 / 2)", PyType::Int},
        {"1 // 0.1", "round((1 - 1 % 0.1) / 0.1)", PyType::Int},  // Python's 9, not floor(10.0)
        {"random.random() // 0.5", "floor(random() / 0.5)", PyType::Int},
        {"-7 % 2", "-7 % 2", PyType::Int},
        {"2 ** 3", "pow(2, 3)", PyType::Float},
        {"-2 ** 2", "-pow(2, 2)", PyType::Float},
        {"2 ** -1", "pow(2, -1)", PyType::Float},
        {"(1 + 2) * 3", "(1 + 2) * 3", PyType::Int},
        {"1 - (2 - 3)", "1 - (2 - 3)", PyType::Int},
        {"(1 - 2) - 3", "(1 - 2) - 3", PyType::Int},
        {"1 + 2.5", "1 + 2.5", PyType::Float},
        {"--ii", "-(-ii)", PyType::Int},
        {"+fi", "fi", PyType::Float},
        {"v1 * v1", "dot(v1, v1)", PyType::Float},
        {"2 * v1 - v2 / 3", "2 * v1 - v2 / 3", PyType::Vec2},
        {"-v1", "-v1", PyType::Vec2},
        {"d * 2", "(b.pos - a.pos) * 2", PyType::Vec2},
        {"si + 'x'", "si + \"x\"", PyType::String},
        {"mystery + 1", "mystery + 1", PyType::Unknown},
        {"mystery + v1", "mystery + v1", PyType::Vec2},
        {"float(h_floor.attr['width']) - (5 + float(h_floor.attr['width']) % 5)",
         "h_floor.width - (5 + h_floor.width % 5)", PyType::Float},
        {"float(old.attr['height']) - (10 + (float(old.attr['height']) % 10) / (float(old.attr['height']) // 10))",
         "old.height - (10 + (old.height % 10) / floor(old.height / 10))", PyType::Float},
        {"A + normalize(v1) * (10 + (float(house.attr['height']) % 10) / (float(house.attr['height']) // 10))",
         "A + normalize(v1) * (10 + (house.height % 10) / floor(house.height / 10))", PyType::Vec2},
    });
}

TEST_CASE("python import translates comparisons and logic", "[import]") {
    expectAll({
        {"1 < 2", "1 < 2", PyType::Bool},
        {"ii == 2.5", "ii == 2.5", PyType::Bool},
        {"si != 'a'", "si != \"a\"", PyType::Bool},
        {"v1 == v2", "v1 == v2", PyType::Bool},
        {"1 < ii < 3", "(1 < ii) and (ii < 3)", PyType::Bool},
        {"1 < ii <= 3 == fi", "(1 < ii) and (ii <= 3) and (3 == fi)", PyType::Bool},
        {"bi and fi > 1 or not bi", "(bi and fi > 1) or !bi", PyType::Bool},
        {"bi or fi > 1 and bi", "bi or (fi > 1 and bi)", PyType::Bool},
        {"not 1 == 2", "!(1 == 2)", PyType::Bool},
        {"not ii", "ii == 0", PyType::Bool},
        {"not fi + 1", "fi + 1 == 0", PyType::Bool},
        {"not si", "si == \"\"", PyType::Bool},
        {"not not bi", "!(!bi)", PyType::Bool},
        {"not mystery", "!mystery", PyType::Bool},
        {"(ii < 2) == bi", "(ii < 2) == bi", PyType::Bool},
        {"bool(ii)", "ii != 0", PyType::Bool},
        {"bool(si)", "si != \"\"", PyType::Bool},
        {"bool(bi)", "bi", PyType::Bool},
    });
}

TEST_CASE("python import reads the attributes of matched elements", "[import]") {
    expectAll({
        {"float(arg0.attr['length'])/2", "arg0.length / 2", PyType::Float},
        {"arg0.attr['length']", "arg0.length", PyType::Float},
        {"float(arg0.attr['size'])/2", "arg0.size / 2", PyType::Float},
        {"-float(arg0.attr['size'])/2", "-arg0.size / 2", PyType::Float},
        {"-float(v_floor.attr['width']) / 2", "-v_floor.width / 2", PyType::Float},
        {"float(arg0.attr['height'])-10", "arg0.height - 10", PyType::Float},
        {"int(old.attr['floors'])+1", "old.floors + 1", PyType::Int},
        {"int(arg0.attr['num_leaves'])", "arg0.num_leaves", PyType::Int},
        {"house.attr['floors']", "house.floors", PyType::Int},
        {"v_floor.attr['floor']", "v_floor.floor", PyType::Int},
        {"trunk.attr['width']", "trunk.width", PyType::Float},
        {"float(trunk.attr['width']) * width_decrease", "trunk.width * width_decrease", PyType::Float},
        {"(float(arg0.attr['x']) + float(arg1.attr['x']))/2", "(arg0.pos.x + arg1.pos.x) / 2", PyType::Float},
        {"1/2*(float(arg0.attr['y'])+float(arg1.attr['y']))+1/3*(float(arg0.attr['x'])-float(arg1.attr['x']))",
         "1 / 2 * (arg0.pos.y + arg1.pos.y) + 1 / 3 * (arg0.pos.x - arg1.pos.x)", PyType::Float},
        {"float(arg0.attr['x'])*2/3+float(arg1.attr['x'])*1/3", "arg0.pos.x * 2 / 3 + arg1.pos.x * 1 / 3", PyType::Float},
        {"arg0.attr[\"y\"]", "arg0.pos.y", PyType::Float},
        {"arg0.x + arg0.y", "arg0.pos.x + arg0.pos.y", PyType::Float},
        {"A + Vec(x1=0, y1=float(house.attr['height']))", "A + (0, house.height)", PyType::Vec2},
        {"A + Vec(x1=0.2, y1=0) + v1 * float(top_edge.attr['blind_portion'])",
         "A + (0.2, 0) + v1 * top_edge.blind_portion", PyType::Vec2},
    });
}

TEST_CASE("python import translates mother conditions", "[import]") {
    expectAll({{"int(attr) < int(attrs['max_leaves'])", "m.num_leaves < m.max_leaves", PyType::Bool}},
              condition("num_leaves"));
    expectAll({{"attr=='Wall' or attr=='x'", "m.label == \"Wall\" or m.label == \"x\"", PyType::Bool},
               {"attr==\"FloorEnd\" or attr==\"HouseEnd\"", "m.label == \"FloorEnd\" or m.label == \"HouseEnd\"", PyType::Bool},
               {"attr=='Branch'", "m.label == \"Branch\"", PyType::Bool},
               {"not attr", "m.label == \"\"", PyType::Bool}},
              condition("label"));
    expectAll({{"not attr", "!m.grown", PyType::Bool}, {"attr==False", "m.grown == false", PyType::Bool}},
              condition("grown"));
    expectAll({{"attr==0", "m.floor == 0", PyType::Bool}, {"not attr", "m.floor == 0", PyType::Bool}},
              condition("floor"));
    expectAll({{"float(attr)>=2 and float(attr)<4", "m.length >= 2 and m.length < 4", PyType::Bool},
               {"float(attr)>3", "m.length > 3", PyType::Bool}},
              condition("length"));
    expectAll({{"int(attr) < max_num_dots", "m.num_dots < max_num_dots", PyType::Bool},
               {"int(attr) >= max_num_lines - 1", "m.num_dots >= max_num_lines - 1", PyType::Bool}},
              condition("num_dots"));
    expectFailures({{"attrs['nope'] > 1", "the grammar has no node attribute `nope`", 6},
                    {"attrs", "`attrs` is supported only as `attrs['key']`", 0}},
                   condition("num_dots"));
    // Outside a condition `attr` is not a name.
    expectFailures({{"attr == 1", "unknown name `attr`", 0}});
}

TEST_CASE("python import translates conditional expressions", "[import]") {
    expectAll({
        {"0 if center.attr['direction'] == 'horizontal' else pi/2",
         "(center.direction == \"horizontal\" ? 0 : pi / 2)", PyType::Float},
        {"(np.arctan2(v1.y, v1.x) * 180 / pi if v1.x != 0 else 90)",
         "(v1.x != 0 ? atan2(v1.y, v1.x) * 180 / pi : 90)", PyType::Float},
        {"(np.arctan2(v1.y, v1.x) * 180 / pi if v1.x != 0 else 90) * random.uniform(0.9, 1.1)",
         "(v1.x != 0 ? atan2(v1.y, v1.x) * 180 / pi : 90) * uniform(0.9, 1.1)", PyType::Float},
        {"(np.arctan2(v1.y, v1.x) * 180 / pi if v1.x != 0 else 90) - 30",
         "(v1.x != 0 ? atan2(v1.y, v1.x) * 180 / pi : 90) - 30", PyType::Float},
        {"1 if bi else 2 if ii > 3 else 3", "(bi ? 1 : (ii > 3 ? 2 : 3))", PyType::Int},
        {"1 if ii else 2", "(ii != 0 ? 1 : 2)", PyType::Int},
        {"'a' if si else 'b'", "(si != \"\" ? \"a\" : \"b\")", PyType::String},
        {"v1 if bi else v2", "(bi ? v1 : v2)", PyType::Vec2},
        {"mystery if bi else 2.5", "(bi ? mystery : 2.5)", PyType::Float},
    });
}

TEST_CASE("python import translates the tool's library", "[import]") {
    expectAll({
        {"B + Vec(vec1=A, vec2=rotate(B, pi/2 * random.choice((-1,1)) * (random.random() / 3 + 0.3), A)) * 0.6",
         "B + (rotate(B, pi / 2 * choice(-1, 1) * (random() / 3 + 0.3), A) - A) * 0.6", PyType::Vec2},
        {"rotate(Vec(self_), rot_deg, C)", "rotate(placed, rot_deg, C)", PyType::Vec2},
        {"rotate(A + v1 / 4 * 0.5, rot_deg, C)", "rotate(A + v1 / 4 * 0.5, rot_deg, C)", PyType::Vec2},
        {"c + rotate(v1, 2 * pi * (int(leave.attr['number']) / int(center.attr['max_leaves'])), c)",
         "c + rotate(v1, 2 * pi * (leave.number / center.max_leaves), c)", PyType::Vec2},
        {"rotate(v1, pi)", "rotate(v1, pi)", PyType::Vec2},
        {"Vec(a)", "a.pos", PyType::Vec2},
        {"Vec(self_)", "placed", PyType::Vec2},
        {"Vec(a, b)", "(b.pos - a.pos)", PyType::Vec2},
        {"Vec(a, b) * 2", "(b.pos - a.pos) * 2", PyType::Vec2},
        {"Vec(x1=-0.2, y1=-0.05)", "(-0.2, -0.05)", PyType::Vec2},
        {"Vec(1, 2, 3.5, fi + 1)", "(3.5 - 1, fi + 1 - 2)", PyType::Vec2},
        {"Vec(x1=1, y1=2, x2=3, y2=4 - ii)", "(3 - 1, 4 - ii - 2)", PyType::Vec2},
        {"Vec(vec1=A)", "A", PyType::Vec2},
        {"Vec(vec1=A, vec2=B)", "(B - A)", PyType::Vec2},
        {"Vec(vec1=A, vec2=B).x", "(B - A).x", PyType::Float},
        {"(A + B).y", "(A + B).y", PyType::Float},
        {"self_.x", "placed.x", PyType::Float},
        {"norm(v1)", "length(v1)", PyType::Float},
        {"norm(v1) * 0.5", "length(v1) * 0.5", PyType::Float},
        {"normalize(v1)", "normalize(v1)", PyType::Vec2},
        {"perp_right(v1)", "perp_right(v1)", PyType::Vec2},
        {"cross(v1, v2)", "cross(v1, v2)", PyType::Float},
        {"angle(v1, v2)", "abs(angle(v1, v2))", PyType::Float},
        {"np.arctan2(v1.y, v1.x)", "atan2(v1.y, v1.x)", PyType::Float},
        {"np.sin(fi) + np.cos(0) + np.sqrt(4) + sqrt(4)", "sin(fi) + cos(0) + sqrt(4) + sqrt(4)", PyType::Float},
        {"asin(1) + acos(1) + atan(1) + np.arcsin(1)", "asin(1) + acos(1) + atan(1) + asin(1)", PyType::Float},
        {"math.pi + np.pi + pi", "pi + pi + pi", PyType::Float},
        {"math.floor(fi) + np.ceil(fi)", "floor(fi) + ceil(fi)", PyType::Int},
        {"random.random()", "random()", PyType::Float},
        {"random.uniform(0.05, 0.95)", "uniform(0.05, 0.95)", PyType::Float},
        {"random.randint(5,15)", "randint(5, 15)", PyType::Int},
        {"random.choice((0.0, 1.0))", "choice(0.0, 1.0)", PyType::Float},
        {"random.choice([1, 2.5, 3])", "choice(1, 2.5, 3)", PyType::Float},
        {"random.choice(('a', 'b'))", "choice(\"a\", \"b\")", PyType::String},
        {"random.choice((7,))", "7", PyType::Int},
        {"random.gauss(0, 1)", "normal(0, 1)", PyType::Float},
        {"abs(-3) + abs(fi)", "abs(-3) + abs(fi)", PyType::Float},
        {"abs(ii)", "abs(ii)", PyType::Int},
        {"min(1, 2) + max(1, 2)", "min(1, 2) + max(1, 2)", PyType::Int},
        {"max(1, fi, 3)", "max(1, fi, 3)", PyType::Float},
        {"min((1, 2.5))", "min(1, 2.5)", PyType::Float},
        {"round(fi)", "round(fi)", PyType::Int},
        {"pow(2, ii)", "pow(2, ii)", PyType::Float},
        {"int(ii)", "ii", PyType::Int},
        {"int(fi)", "int(fi)", PyType::Int},
        {"int(si)", "int(si)", PyType::Int},
        {"float(ii)", "ii", PyType::Float},
        {"float(fi)", "fi", PyType::Float},
        {"float(si)", "float(si)", PyType::Float},
        {"str(ii)", "str(ii)", PyType::String},
        {"str(si)", "si", PyType::String},
    });
}

TEST_CASE("python import writes f-strings as format calls", "[import]") {
    // .svg_d of pattern_circle.yml.
    expectAll({
        {"f'M {s.x*35} {s.y*35} Q {(s + rotate(v1, 2*pi*0.05, s)).x*35} {(s + rotate(v1, 2*pi*0.05, s)).y*35} "
         "{e.x*35} {e.y*35} Q {(s + rotate(v1, -2*pi*0.05, s)).x*35} {(s + rotate(v1, -2*pi*0.05, s)).y*35} "
         "{s.x*35} {s.y*35}'",
         "format(\"M {} {} Q {} {} {} {} Q {} {} {} {}\", s.x * 35, s.y * 35, "
         "(s + rotate(v1, 2 * pi * 0.05, s)).x * 35, (s + rotate(v1, 2 * pi * 0.05, s)).y * 35, e.x * 35, e.y * 35, "
         "(s + rotate(v1, -2 * pi * 0.05, s)).x * 35, (s + rotate(v1, -2 * pi * 0.05, s)).y * 35, s.x * 35, s.y * 35)",
         PyType::String},
        {"f'Q {(s + rotate(v1, 2*pi*float(arg0.attr[\"control_degree\"]), s)*float(arg0.attr[\"control_position\"])).x*35}'",
         "format(\"Q {}\", (s + rotate(v1, 2 * pi * arg0.control_degree, s) * arg0.control_position).x * 35)",
         PyType::String},
        {"f'{fi:.2f} {{x}} \"{si}\"'", "format(\"{:.2} {{x}} \\\"{}\\\"\", fi, si)", PyType::String},
        {"f'{ii:.0f}'", "format(\"{:.0}\", ii)", PyType::String},
        {"f'plain {{x}}'", "\"plain {x}\"", PyType::String},
        {"f\"{'a' if bi else 'b'}!\"", "format(\"{}!\", (bi ? \"a\" : \"b\"))", PyType::String},
    });
    expectFailures({
        {"f'{v1}'", "a vector in an f-string prints differently in g2d; format its `.x` and `.y`", 3},
        {"f'ab{zz}'", "unknown name `zz`", 5},
        {"f'{fi:>5}'", "the format spec `:>5` is not supported; g2d knows `{:.N}` (N = 0…17 decimals, Python's `:.Nf`)", 6},
        {"f'{fi:.20f}'", "the format spec `:.20f` is not supported; g2d knows `{:.N}` (N = 0…17 decimals, Python's `:.Nf`)", 6},
        {"f'{si:.2f}'", "the format spec `:.2f` needs a number, got string", 6},
        {"f'{fi!r}'", "conversions (`!r`, `!s`) in f-strings are not supported", 5},
        {"f'{fi=}'", "self-documenting `=` in an f-string is not supported", 5},
        {"f'{}'", "empty expression in an f-string", 2},
        {"f'a}'", "single `}` in an f-string; write `}}`", 3},
        {"f'{'", "unterminated `{` in an f-string", 2},
        {"f'a' 'b'", "implicit concatenation with an f-string is not supported; write one f-string", 5},
    });
}

TEST_CASE("python import reports what g2d cannot express", "[import]") {
    expectFailures({
        {"float(trunk.attr['.svg_stroke_width']) * 0.7",
         "the style property `.svg_stroke_width` cannot be read in g2d; store the value in an attribute", 17},
        {"trunk.attr['.svg_stroke_width']",
         "the style property `.svg_stroke_width` cannot be read in g2d; store the value in an attribute", 11},
        {"old.attr['.generation']", "`.generation` has no g2d counterpart (g2d's `age` is the step that created the element)", 9},
        {"old.attr['nope']", "the grammar has no node attribute `nope`", 9},
        {"trunk.attr['x']", "an edge has no `x`", 11},
        {"arg0.attr[k]", "the attribute key must be a string literal", 10},
        {"arg0.attr", "`arg0.attr` is supported only as `arg0.attr['key']`", 4},
        {"arg0.size", "`.size` of a matched element is not supported; read `arg0.attr['size']`", 4},
        {"arg0 + 1", "`arg0` is a matched element, not a value; read an attribute (`arg0.attr['key']`) or its position (`Vec(arg0)`)", 0},
        {"self_", "`self_` is supported only as `Vec(self_)`", 0},
        {"self_.attr['size']", "reading the attributes of `self_` is not supported; use the matched element's", 0},
        {"v1[0]", "subscripts are supported only as `X.attr['key']`", 2},
        {"zz + 1", "unknown name `zz`", 0},
        {"foo(1)", "unknown function `foo`", 0},
        {"sin(1)", "unknown function `sin`; write `np.sin(…)`", 0},
        {"isnan(fi)", "`isnan` has no g2d counterpart", 0},
        {"np.isinf(fi)", "`np.isinf` has no g2d counterpart", 0},
        {"random.shuffle(v1)", "`random.shuffle` has no g2d counterpart", 0},
        {"scipy.stats.norm(1)", "`scipy.stats.norm` has no g2d counterpart", 0},
        {"random.random", "`random.random` is a function; call it", 0},
        {"norm", "the function `norm` is not a value; call it", 0},
        {"si.upper()", "method calls (`.upper(…)`) are not supported", 2},
        {"lambda x: x", "`lambda` expressions are not supported", 0},
        {"[x for x in v1]", "list comprehensions are not supported", 3},
        {"sum(x for x in v1)", "generator expressions are not supported", 6},
        {"{1: 2}", "dict and set literals are not supported", 0},
        {"[1, 2]", "lists are not supported", 0},
        {"(1, 2)", "tuples are not values in g2d; a vector is `Vec(x1=a, y1=b)`", 0},
        {"1, 2", "a bare tuple `a, b` is not supported", 1},
        {"si + 1", "`+` cannot combine string and int; convert with str(…) or use an f-string", 3},
        {"si * 2", "`*` cannot combine string and int; string repetition has no g2d counterpart", 3},
        {"'%d' % ii", "printf-style `%` formatting is not supported; use an f-string", 5},
        {"bi + 1", "`+` cannot combine bool and int; arithmetic on bools needs int(…) in g2d", 3},
        {"v1 / v2", "`/` cannot combine vec2 and vec2", 3},
        {"v1 < v2", "`<` needs numbers, got vec2 and vec2", 3},
        {"si < 'b'", "strings are not ordered in g2d", 3},
        {"si == 1", "`==` cannot compare string and int", 3},
        {"ii is None", "`is` is not supported; compare with `==` or `!=`", 3},
        {"ii in v1", "`in` is not supported", 3},
        {"ii == None", "comparison with `None` is not supported", 3},
        {"None + 1", "`None` has no g2d value", 5},
        {"ii and bi", "`and` takes bools in g2d, got int; compare explicitly (e.g. `x != 0`)", 3},
        {"bi or si", "`or` takes bools in g2d, got string; compare explicitly (e.g. `x != 0`)", 3},
        {"not v1", "`not` of a vec2 has no g2d counterpart", 0},
        {"1 if bi else 'a'", "the branches of `if`-`else` have different types: int and string", 2},
        {"1 | 2", "the operator `|` is not supported; for bools write `or`", 2},
        {"~ii", "the bitwise operator `~` is not supported", 0},
        {"-si", "unary `-` needs a number or a vector, got string", 0},
        {"v1.z", "the attribute `.z` is not supported", 2},
        {"fi.x", "`.x` needs a vector, got float", 2},
        {"Vec(v1)", "`Vec(v)` needs a matched node or `self_`; for a vector value write `Vec(vec1=v)`", 4},
        {"Vec(trunk)", "`trunk` is an edge, which has no position", 4},
        {"Vec(1, 2)", "`Vec(v)` needs a matched node or `self_`; for a vector value write `Vec(vec1=v)`", 4},
        {"Vec(x1='a', y1=2)", "`x1` of `Vec` must be a number, got string", 7},
        {"Vec(x1=1)", "`Vec` keywords must be x1, y1 (with x2, y2) or vec1 (with vec2)", 0},
        {"Vec(a, vec1=A)", "`Vec` with both positional and keyword arguments is not supported", 0},
        {"Vec(x1=1, x1=2)", "the keyword `x1` is given twice", 13},
        {"Vec(1, 2, 3)", "`Vec` takes a node, two nodes, four numbers or keywords (x1=, y1= or vec1=, vec2=); got 3 arguments", 0},
        {"norm(v1, v2)", "`norm` takes 1 argument, got 2", 0},
        {"norm(fi)", "argument 1 of `norm` must be a vector, got float", 5},
        {"rotate(v1, v2)", "argument 2 of `rotate` must be a number, got vec2", 11},
        {"sqrt(si)", "argument 1 of `sqrt` must be a number, got string", 5},
        {"np.arctan2(1)", "`np.arctan2` takes 2 arguments, got 1", 0},
        {"random.randint(1, 2.5)", "argument 2 of `random.randint` must be an int, got float", 18},
        {"random.choice(v1)", "`random.choice` needs its choices written inline, as in `random.choice((a, b))`", 0},
        {"random.choice((1, 'a'))", "the choices of `random.choice` must have one type, got int and string", 18},
        {"random.choice(())", "`random.choice` of an empty sequence", 14},
        {"sqrt(x=1)", "keyword arguments are supported only in `Vec(…)`", 7},
        {"int(v1)", "`int` of a vec2 has no g2d counterpart", 4},
        {"x := 1", "assignment expressions (`:=`) are not supported", 2},
        {"v1[1:2]", "slices are not supported", 4},
        {"1 ! 2", "`!` is not Python; write `not`", 2},
        {"a && b", "`&&` is not Python; write `and`", 2},
        {"bi || bi", "`||` is not Python; write `or`", 3},
        {"bi & bi", "the operator `&` is not supported; for bools write `and`", 3},
        {"b'x'", "bytes literals are not supported", 0},
        {"1j", "complex numbers are not supported", 0},
        {"1e400", "float literal `1e400` is out of range", 0},
        {"99999999999999999999", "integer literal too large for g2d's 64-bit int", 0},
        {"007", "leading zeros in an integer literal are not Python", 0},
    });
}

TEST_CASE("python import survives garbage", "[import]") {
    expectFailures({
        {"", "empty expression", 0},
        {"   ", "empty expression", 3},
        {"(", "unexpected end of expression", 1},
        {"1 +", "unexpected end of expression", 3},
        {"f'{", "unterminated string", 0},
        {"'abc", "unterminated string", 0},
        {"(1 + 2", "expected `)`, found end of expression", 6},
        {"1 if bi", "expected `else` of a conditional expression, found end of expression", 7},
        {"1 2", "unexpected `2`", 2},
        {"a.", "expected a name after `.`, found end of expression", 2},
        {"$", "unexpected character `$`", 0},
        {"if", "unexpected `if`", 0},
        {"'\\xZZ'", "truncated \\x escape in a string", 0},
        {"'é' + é", "unexpected character", 6},
    });
    const std::vector<std::string> hostile = {
        std::string(10000, '('),
        std::string(10000, '(') + "1" + std::string(10000, ')'),
        std::string(10000, '-') + "1",
        std::string(10000, '['),
        [] { std::string s; for (int i = 0; i < 3000; ++i) s += "not "; return s + "bi"; }(),
        [] { std::string s = "1"; for (int i = 0; i < 3000; ++i) s += " + 1"; return s; }(),
        [] { std::string s = "2"; for (int i = 0; i < 3000; ++i) s += " ** 2"; return s; }(),
        [] { std::string s = "v1"; for (int i = 0; i < 3000; ++i) s += ".x"; return s; }(),
        [] { std::string s; for (int i = 0; i < 3000; ++i) s += "f'{"; return s; }(),
        [] { std::string s = "1"; for (int i = 0; i < 3000; ++i) s += " if bi else 1"; return s; }(),
        std::string("\xff\xfe", 2),
    };
    for (const std::string& source : hostile) {
        INFO(source.substr(0, 40));
        const PyTranslation r = translatePython(source, context());
        CHECK_FALSE(r.ok);
        CHECK_FALSE(r.problem.empty());
        CHECK(r.problem.find('\n') == std::string::npos);
        CHECK(r.column >= 0);
        CHECK(r.column <= static_cast<int>(source.size()));
    }
    // Nesting up to the limit is fine.
    const PyTranslation deep = translatePython(std::string(150, '(') + "ii" + std::string(150, ')'), context());
    CHECK(deep.ok);
    CHECK(deep.text == "ii");
    // The problem is one line even when a quoted key holds a newline.
    const PyTranslation key = translatePython("arg0.attr['a\\nb']", context());
    CHECK_FALSE(key.ok);
    CHECK(key.problem == "the attribute key `a b` is not a g2d name");
    // A context that knows nothing still answers.
    const PyTranslation bare = translatePython("x + 1", PyContext{});
    CHECK_FALSE(bare.ok);
    CHECK(bare.problem == "unknown name `x`");
}

TEST_CASE("python import names its types", "[import]") {
    CHECK(pyTypeName(PyType::Unknown) == "unknown");
    CHECK(pyTypeName(PyType::Bool) == "bool");
    CHECK(pyTypeName(PyType::Int) == "int");
    CHECK(pyTypeName(PyType::Float) == "float");
    CHECK(pyTypeName(PyType::String) == "string");
    CHECK(pyTypeName(PyType::Vec2) == "vec2");
    CHECK(pyTypeName(PyType::None) == "none");
}

TEST_CASE("an import declares the names its code reads, directly or through another, not those only a comment names",
          "[import]") {
    using g2d::import::usedNames;
    const std::vector<std::pair<std::string, std::string>> declared = {
        {"a", "b * 2"}, {"b", "3"}, {"c", "d + 1"}, {"d", "1"}, {"e", "\"x // not a comment\" + f"}, {"f", "2"}};
    // `c` only in a comment; `a` reads `b`; the string's `//` does not end the code.
    CHECK(usedNames("x = a + 1;   // c\n// c is not read\ny = \"//\" + e;", declared) == std::set<std::string>{"a", "b", "e", "f"});
    CHECK(usedNames("x = ab + a_b;", declared).empty());   // whole words only
}

TEST_CASE("an import's long lines are wrapped at their shallowest separators, strings and short lines untouched", "[import]") {
    using g2d::import::wrapLongLines;
    const std::string shortLine = "    n: Vertex @ (0, 0) where n.label == \"a, b and c\";";
    CHECK(wrapLongLines(shortLine, 60) == shortLine);
    // ` and ` at depth 0 first; a string's separators are not cut.
    CHECK(wrapLongLines("        n: Vertex @ (1, 2) where n.has_w and (n.w > 3) and n.label == \"a, b and c\";", 50) ==
          "        n: Vertex @ (1, 2) where n.has_w\n"
          "            and (n.w > 3)\n"
          "            and n.label == \"a, b and c\";");
    // An assignment block: its `, ` inside `{ }`; a piece still too long is broken inside its call.
    CHECK(wrapLongLines("    e { d = format(\"M {} {}\", s.x, s.y, t.x, t.y), fill = \"red\" };", 40) ==
          "    e { d = format(\"M {} {}\", s.x, s.y,\n"
          "            t.x, t.y),\n"
          "        fill = \"red\" };");
    // A trailing comment goes above its code; comment lines stay.
    CHECK(wrapLongLines("    x = aaaa, bbbb;   // why\n// a long comment line, and more, and more", 16) ==
          "    // why\n    x = aaaa,\n        bbbb;\n// a long comment line, and more, and more");
}

TEST_CASE("an import's names avoid every keyword, type, built-in and fact the checker knows", "[import]") {
    std::vector<std::string> all = g2d::front::keywords();
    for (const auto& b : g2d::sema::builtinFunctions()) all.push_back(b.name);
    for (const auto& f : g2d::sema::elementFacts()) all.push_back(f.name);
    for (const char* other : {"int", "float", "vec2", "pi", "tau", "placed", "canvas", "weight"}) all.push_back(other);
    for (const auto& name : all) {
        INFO(name);
        g2d::import::NameSet names(g2d::front::reservedNames());
        CHECK(names.take(name) == name + "_");
    }
    g2d::import::NameSet names(g2d::front::reservedNames());
    CHECK(names.take("floor_plan") == "floor_plan");
}
