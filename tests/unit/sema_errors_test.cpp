// Every compile-time diagnostic of the checker: its text and its location.
#include <catch2/catch.hpp>

#include "test_helpers.hpp"

using g2d::test::compile;
using g2d::test::firstError;
using g2d::test::prelude;

namespace {

struct Case {
    const char* what;
    std::string source;    // appended to the prelude (which has 4 lines)
    std::string expected;  // "LINE:COL: MESSAGE" of the first error
};

void checkCases(const std::vector<Case>& cases) {
    for (const auto& c : cases) {
        INFO(c.what << "\n" << c.source);
        auto r = compile(prelude() + c.source);
        CHECK(firstError(r) == c.expected);
        CHECK_FALSE(r.program.has_value());
    }
}

}  // namespace

TEST_CASE("unknown names are reported with suggestions", "[sema][names]") {
    checkCases({
        {"unknown node kind", "rule R { match { x: Q; } produce { } }",
         "5:21: unknown node kind `Q`"},
        {"unknown node kind, close to a known one", "rule R { match { x: PP; } produce { } }",
         "5:21: unknown node kind `PP`; did you mean `P`?"},
        {"edge kind where a node kind is needed", "rule R { match { x: E; } produce { } }",
         "5:21: `E` is an edge kind, but a node needs a node kind"},
        {"unknown attribute", "rule R { match { x: P where x.ww > 0; } produce { x; } }",
         "5:31: node kind `P` has no attribute `ww`; did you mean `w`?"},
        {"unknown parameter or name", "rule R { match { x: P where x.w > limitt; } produce { x; } }",
         "5:35: unknown name `limitt`"},
        {"unknown function", "rule R { match { x: P where sine(x.w) > 0; } produce { x; } }",
         "5:29: unknown function `sine`; did you mean `sin`?"},
        {"unknown type", "param k: integer = 1;", "5:10: unknown type `integer`"},
        {"unknown enum value", "enum Dir { Up, Down }\nconst d = Dir.Left;", "6:15: enum `Dir` has no value `Left`"},
        {"element used as a value", "rule R { match { x: P where x > 0; } produce { x; } }",
         "5:29: `x` is a node, not a value; read one of its attributes or `x.pos` instead"},
    });
}

TEST_CASE("type mismatches", "[sema][types]") {
    checkCases({
        {"vec2 < float", "rule R { match { x: P where x.pos < 1.0; } produce { x; } }",
         "5:35: operator `<` cannot combine vec2 and float"},
        {"string where a number is needed", "const c = \"a\" - 1;", "5:15: operator `-` cannot combine string and int"},
        {"string + number", "const c = \"a\" + 1;",
         "5:15: operator `+` cannot combine string and int; convert with str(…) or use format(…)"},
        {"condition must be bool", "rule R { match { x: P where x.w; } produce { x; } }",
         "5:29: a `where` condition must be bool, but this is float"},
        {"attribute assignment", "rule R { match { x: P; } produce { x { w = \"big\" }; } }",
         "5:44: attribute `w` must be float, but this is string"},
        {"vec2 * vec2", "const v = (1, 2) * (3, 4);",
         "5:18: operator `*` cannot multiply two vec2s; use dot(a, b) or cross(a, b)"},
        {"not on a number", "const b = not 3;", "5:11: `not` needs a bool, but this is int"},
        {"branches differ", "const c = true ? 1 : \"one\";",
         "5:11: the two branches of `?:` have different types: int and string"},
        {"param default type", "param n: int = 2.5;", "5:16: the default of parameter `n` must be int, but this is float"},
        {"integer overflow", "const big = 99999999999999999999;",
         "5:13: integer literal is out of range (at most 9223372036854775807)"},
    });
}

TEST_CASE("wrong arity and argument types of functions", "[sema][calls]") {
    checkCases({
        {"too few arguments", "const v = rotate((1, 0));",
         "5:11: `rotate` takes 2 to 3 arguments, got 1 (rotate(v: vec2, angle: float[, centre: vec2]) -> vec2, "
         "rotate(v: vec3, axis: vec3, angle: float) -> vec3)"},
        {"wrong argument type", "const v = perp_left(3.0);",
         "5:21: argument 1 of `perp_left` must be vec2, got float (perp_left(v: vec2) -> vec2)"},
        {"no overload", "const v = length(3.0);", "5:11: no version of `length` takes (float) (length(v: vec2|vec3) -> float)"},
        {"user function arity", "fn twice(x: float) -> float = 2 * x;\nconst y = twice(1, 2);",
         "6:11: `twice` takes 1 argument, got 2"},
        {"format placeholders", "const s = format(\"{} {}\", 1);",
         "5:18: format template has 2 placeholders but 1 value is given"},
        {"format template literal", "const t = \"{}\";\nconst s = format(t, 1);",
         "6:18: the template of `format` must be a string literal"},
        {"recursion", "fn f(x: int) -> int = f(x - 1);", "5:23: function `f` cannot call itself (no recursion)"},
        {"random in a match", "rule R { match { x: P where x.w < random(); } produce { x; } }",
         "5:35: random function `random` cannot be used in a match condition; draw the value when the element is created, into an attribute (`n: K { r = random(…) }` in the daughter that makes it), and test the attribute"},
    });
}

TEST_CASE("duplicate names", "[sema][duplicates]") {
    checkCases({
        {"duplicate kind", "node P;", "5:6: `P` is already declared"},
        {"duplicate parameter", "param k: int = 1;\nparam k: int = 2;", "6:7: `k` is already declared"},
        {"duplicate attribute", "node Q { a: int; a: float; }", "5:18: kind `Q` already has an attribute `a`"},
        {"duplicate element in a match", "rule R { match { x: P; x: P; } produce { } }",
         "5:24: `x` is already declared in this production"},
        {"duplicate rule", "rule R { match { x: P; } produce { x; } }\nrule R { match { x: P; } produce { x; } }",
         "6:6: a rule named `R` already exists"},
        {"hiding a builtin", "fn sin(x: float) -> float = x;", "5:4: function `sin` would hide the built-in `sin`"},
        {"second axiom", "axiom { }", "5:1: a grammar has exactly one axiom, but this is a second one"},
        {"reserved attribute", "node Q { pos: vec2; }",
         "5:10: `pos` is a built-in fact of every element and cannot be declared as an attribute"},
    });
}

TEST_CASE("graph structure errors", "[sema][graphs]") {
    checkCases({
        {"edge endpoint not a node", "rule R { match { x: P; x -[E]-> y; } produce { } }",
         "5:33: edge endpoint `y` is not a node of the match"},
        {"edge endpoint is an edge", "rule R { match { x: P; y: P; e: x -[E]-> y; x -[E]-> e; } produce { } }",
         "5:54: edge endpoint `e` is an edge, not a node"},
        {"directed kind, undirected arrow", "rule R { match { x: P; y: P; x -[E]- y; } produce { } }",
         "5:34: edge kind `E` is directed: write `a -[E]-> b`"},
        {"undirected kind, directed arrow", "rule R { match { x: P; y: P; x -[U]-> y; } produce { } }",
         "5:34: edge kind `U` is undirected: write `a -[U]- b` (or declare it `edge U directed`)"},
        {"kind change", "node Q;\nrule R { match { x: P; } produce { x: Q; } }",
         "6:39: kept node `x` cannot change its kind from `P` to `Q`"},
        {"edge kind change", "rule R { match { x: P; y: P; e: x -[E]-> y; } produce { e: x -[U]- y; } }",
         "5:64: kept edge `e` cannot change its kind from `E` to `U`"},
        {"daughter references an unbound name", "rule R { match { x: P; } produce { x -[E]-> z; } }",
         "5:45: unknown name `z`: it is not a node of the match or this daughter"},
        {"daughter references a NAC element",
         "rule R { match { x: P; not { y: P; x -[E]-> y; } } produce { x -[E]-> y; } }",
         "5:71: `y` belongs to a negative condition, which binds nothing the daughter could use"},
        {"new node without position", "rule R { match { x: P; } produce { x; n: P; } }",
         "5:39: new node `n` needs a position: `at EXPR`, or a sketch position `@ (x, y)` for automatic placement"},
        {"automatic placement without sketches", "rule R { match { x: P; } produce { x; n: P @ (1, 0); } }",
         "5:18: automatic placement needs a sketch position for every matched node but wildcards: give `x` one with `@ (x, y)`"},
        {"reading a new element", "rule R { match { x: P; } produce { x; n: P at x.pos; m: P at n.pos; } }",
         "5:62: `n` is created by this production; expressions can read only the matched elements (their values "
         "before the step)"},
        {"ordered needs sketches", "rule R ordered { match { x: P @ (0, 0); y: P; } produce { x; y; } }",
         "5:41: rule `R` is `ordered`: every matched node needs a sketch position; give `y` one with `@ (x, y)`"},
        {"no produce block", "rule R { match { x: P; } }",
         "5:6: rule `R` has no `produce` block (write `produce { }` to delete the whole match)"},
        {"at in a match", "rule R { match { x: P at (0, 0); } produce { x; } }",
         "5:26: a match cannot place nodes (`at`); test positions with `where`"},
        {"where in a daughter", "rule R { match { x: P; } produce { x where x.w > 0; } }",
         "5:44: conditions (`where`) belong in the match"},
        {"unknown pick", "rule R pick newest { match { x: P; } produce { x; } }",
         "5:13: unknown match selection `newest` (use `random` or `oldest`)"},
    });
}

TEST_CASE("keeping an edge keeps its endpoints", "[sema][mapping]") {
    auto r = compile(prelude() + "rule R { match { x: P; y: P; z: P; e: x -[E]-> y; y -[E]-> z; } produce { e; } }");
    REQUIRE(r.program);
    const auto& d = r.program->rules[0].daughters[0];
    CHECK(d.nodes.size() == 2);                      // x and y, kept through e
    CHECK(d.deletedNodes == std::vector<int>{2});    // z goes, with its edge
    CHECK(d.deletedEdges == std::vector<int>{1});
}

TEST_CASE("weights: positive constants, or read from the match", "[sema][weights]") {
    checkCases({
        {"zero weight", "rule R { match { x: P; } produce weight 0 { x; } }",
         "5:41: a weight must be positive, but this is 0"},
        {"negative weight", "rule R { match { x: P; } produce weight -2.5 { x; } }",
         "5:41: a weight must be positive, but this is -2.5"},
        {"random weight", "rule R { match { x: P; } produce weight uniform(1, 2) { x; } }",
         "5:41: random function `uniform` cannot be used in a weight (weights read literals, constants, parameters "
         "and the matched elements)"},
        {"a daughter's new node", "rule R { match { x: P; } produce weight y.w { x; y: P; } }",
         "5:41: unknown name `y`"},
    });
    // A parameter may set a weight (checked when the run starts).
    auto r = compile(prelude() + "param p: float = 2;\nrule R { match { x: P; } produce weight p { x; } }");
    CHECK(firstError(r).empty());
    // A weight may read the match: evaluated per application.
    auto m = compile(prelude() + "rule R { match { x: P; } produce weight x.w * 2 { x; } produce { } }");
    REQUIRE(m.program);
    CHECK(m.program->rules[0].daughters[0].weightReadsMatch);
    CHECK_FALSE(m.program->rules[0].daughters[0].weight);
    CHECK_FALSE(m.program->rules[0].daughters[1].weightReadsMatch);
}

TEST_CASE("wildcards are used only as the thesis allows", "[sema][wildcards]") {
    checkCases({
        {"wildcard in a daughter", "rule R { match { x: P; } produce { x; y: *; } }",
         "5:42: `*` (wildcard) can only be used in a match"},
        {"moving a wildcard", "rule R { match { x: P; w: *; x -[E]-> w; } produce { x; w at (0, 0); } }",
         "5:57: wildcard node `w` is left unchanged by the production; it cannot be moved or assigned"},
        {"reading a wildcard's attribute", "rule R { match { x: P; w: *; x -[E]-> w where w.w > 0; } produce { x; } }",
         "5:49: wildcard node `w` matches any kind, so it has no attribute `w`; only pos, age, generation, id, degree, in_degree, "
         "out_degree, faces can be read"},
        {"isolated wildcard", "rule R { match { x: P; w: *; } produce { x; } }",
         "5:24: wildcard node `w` must be an endpoint of an edge or a corner of a face of the match"},
    });
    auto axiom = compile("node P;\naxiom { a: *; }\n");
    CHECK(firstError(axiom) == "2:12: wildcard nodes (`*`) belong in a rule's match, not in the axiom");
}

TEST_CASE("imports: missing files and cycles", "[sema][imports]") {
    auto missing = compile(prelude() + "import \"no_such_file.g2d\";");
    CHECK(firstError(missing).rfind("5:1: cannot find imported file `no_such_file.g2d`", 0) == 0);
    auto cycle = compile("import \"cycle_a.g2d\";\n" + prelude(), "cycle_main.g2d");
    CHECK(firstError(cycle).find("import cycle: `cycle_a.g2d` → `cycle_b.g2d` → `cycle_a.g2d`") !=
          std::string::npos);
}

TEST_CASE("warnings: unused bindings and rules that can never match", "[sema][warnings]") {
    auto r = compile(prelude() +
                     "node Never;\n"
                     "param unused_param: int = 1;\n"
                     "rule R { match { x: P; } let unused = 1; produce { x { w = 2 }; } }\n"
                     "rule S { match { n: Never; } produce { } }\n"
                     "rule T { match { x: P where 1 > 2; } produce { x { w = 3 }; } }\n");
    REQUIRE(r.program.has_value());
    auto lines = g2d::test::diagnosticLines(r);
    CHECK(lines == std::vector<std::string>{
                       "6:1: warning: parameter `unused_param` is never used",
                       "7:30: warning: `unused` is never used",
                       "8:1: warning: rule `S` can never match: no element of node kind `Never` is ever created (the "
                       "axiom has none and no rule makes one)",
                       "9:6: warning: rule `T` can never match: one of its conditions is always false",
                   });
}

TEST_CASE("warnings: a compound that never has an instance says so, not `rule`", "[sema][warnings][compound]") {
    auto r = compile("node P;\nnode Never;\naxiom { a: P at (0, 0); }\n"
                     "compound C { match { p: P where 1 > 2; } sequence { Grow; } }\n"
                     "compound D { match { n: Never; } sequence { Grow; } }\n"
                     "rule Grow { match { p: P; } produce { p; q: P at p.pos + (1, 0); } }\n"
                     "sequence { C; D; }\n");
    REQUIRE(r.program.has_value());
    CHECK(g2d::test::diagnosticLines(r) ==
          std::vector<std::string>{"4:10: warning: compound `C` never has an instance: one of its conditions is always false",
                                   "5:1: warning: compound `D` never has an instance: no element of node kind `Never` is ever created "
                                   "(the axiom has none and no rule makes one)"});
}

TEST_CASE("warnings: `insert` between corners a matched face has on a diagonal", "[sema][warnings][faces]") {
    auto warnings = [](const std::string& match, const std::string& between) {
        auto r = compile("node P;\nface Q;\naxiom { a: P at (0, 0); b: P at (1, 0); c: P at (1, 1); d: P at (0, 1); Q(a, b, c, d); }\n"
                         "rule R { match { " + match + " a: P; b: P; c: P; d: P; }\n"
                         "produce { a; b; c; d; m: P at (0.5, 0.5); insert m between " + between + "; } }\n");
        REQUIRE(r.program.has_value());
        return g2d::test::diagnosticLines(r);
    };
    const std::string quad = "q: Q(a, b, c, d);";
    CHECK(warnings(quad, "a and c") ==
          std::vector<std::string>{"5:43: warning: `a` and `c` are not neighbouring corners of face `q` (a diagonal), so this `insert` "
                                   "does not grow it: `m` joins only faces with a side from `a` to `c`"});
    CHECK(warnings(quad, "d and b").size() == 1);
    CHECK(warnings(quad, "a and b").empty());   // a side, either way round
    CHECK(warnings(quad, "a and d").empty());
    CHECK(warnings(quad, "b and a").empty());
    // Another matched face has a-c as a side: the insert grows that one.
    CHECK(warnings(quad + " t: Q(a, c, d);", "a and c").empty());
    // A face of any corner count says nothing about its sides.
    CHECK(warnings("q: Q;", "a and c").empty());
}

TEST_CASE("warnings: a face pattern whose corner kinds fit only the mirror image of the faces made", "[sema][warnings][faces]") {
    auto warnings = [](const std::string& pattern, const std::string& more = "") {
        auto r = compile("node Hub;\nnode Left;\nnode Right;\nface Slice;\n"
                         "axiom { h: Hub at (0, 0); l: Left at (1, 0); r: Right at (0, 1); Slice(h, l, r); }\n"
                         "rule Mark { match { h: Hub; l: Left; r: Right; s: " + pattern + "; }\n"
                         "produce { h; l; r; s; n: Hub at (1, 1); } }\n" + more);
        REQUIRE(r.program.has_value());
        return g2d::test::diagnosticLines(r);
    };
    CHECK(warnings("Slice(h, r, l)") ==
          std::vector<std::string>{"6:48: warning: face pattern `s` lists its corners against the order of every `Slice` face the grammar "
                                   "makes, and a face never matches its mirror image: write `s: Slice(l, r, h)`"});
    CHECK(warnings("Slice(l, r, h)").empty());   // a rotation of the face made
    CHECK(warnings("Slice(h, l, r)").empty());
    // A daughter that makes the mirror image too: either order matches something.
    CHECK(warnings("Slice(h, r, l)", "rule Back { match { h: Hub; l: Left; r: Right; } produce { h; l; r; Slice(h, r, l); } }\n").empty());
    // An insert anywhere may give faces corners of other kinds: nothing is known.
    CHECK(warnings("Slice(h, r, l)", "rule Grow { match { h: Hub; l: Left; } produce { h; l; m: Hub at (2, 2); insert m between h and l; } }\n")
              .empty());
}

TEST_CASE("warnings: a rule that changes nothing (as the thesis tool's empty production)", "[sema][warnings]") {
    auto idle = [](const std::string& rules) {
        auto r = compile(prelude() + rules);
        REQUIRE(r.program.has_value());
        std::vector<std::string> out;
        for (const auto& line : g2d::test::diagnosticLines(r))
            if (line.find("changes nothing") != std::string::npos) out.push_back(line);
        return out;
    };
    CHECK(idle("rule Empty { match { } produce { } }\n") ==
          std::vector<std::string>{"5:1: warning: rule `Empty` changes nothing: it keeps its whole match as it is, so it can "
                                   "match at every step and only uses steps up"});
    CHECK(idle("rule Same { match { x: P; y: P; e: x -[E]-> y; } produce { x; y; e; } produce weight 2 { y; x; e; } }\n").size() == 1);
    // Each of these changes something: an attribute, a new node, a deletion, a move, a style, an edge turned round.
    CHECK(idle("rule A { match { x: P; } produce { x { w = 1 }; } }\n"
               "rule B { match { x: P; } produce { x; y: P at (1, 1); } }\n"
               "rule C { match { x: P; y: P; e: x -[E]-> y; } produce { x; y; } }\n"
               "rule D { match { x: P; } produce { x at (2, 2); } }\n"
               "rule F { match { x: P; } produce { x { style.fill = \"red\" }; } }\n"
               "rule G { match { x: P; y: P; e: x -[E]-> y; } produce { x; y; e: y -[E]-> x; } }\n"
               "rule H { match { } produce { } produce { n: P at (0, 0); } }\n")
              .empty());
}

TEST_CASE("warnings: a matched node every daughter deletes, although another rule keeps its kind", "[sema][warnings]") {
    // The slip: `d;` forgotten, so the door goes, and with it its wall.
    const std::string kinds = "node Room;\nnode Door { lit: bool = false; }\nnode Lamp;\nedge Wall;\nedge Cable;\n"
                              "axiom { r: Room; d: Door at (1, 0); r -[Wall]- d; }\n"
                              "rule Paint { match { d: Door where d.lit; } produce { d { lit = false }; } }\n";
    auto warnings = [&](const std::string& light) {
        auto r = compile(kinds + "rule Light { match { r: Room; d: Door where !d.lit; r -[Wall]- d; } " + light + " }\n");
        REQUIRE(r.program.has_value());
        std::vector<std::string> out;
        for (const auto& line : g2d::test::diagnosticLines(r))
            if (line.find("deleted by every daughter") != std::string::npos) out.push_back(line);
        return out;
    };
    CHECK(warnings("produce { r; l: Lamp at d.pos + (0, 0.5); }") ==
          std::vector<std::string>{"8:31: warning: `d` is deleted by every daughter; write `d;` to keep it"});
    CHECK(warnings("produce { r; l: Lamp at d.pos; } produce weight 2 { r; m: Lamp at d.pos + (0, 1); }").size() == 1);
    // Not when the daughter keeps it, names it as an edge's end, or one daughter keeps it.
    CHECK(warnings("produce { r; d { lit = true }; l: Lamp at d.pos; }").empty());
    CHECK(warnings("produce { r; l: Lamp at d.pos; d -[Cable]- l; }").empty());
    CHECK(warnings("produce { r; l: Lamp at d.pos; } produce { r; d; }").empty());
    // Not when the deletion is plainly meant: the daughter makes nothing, puts a
    // door or a wall in its place, or takes its neighbour too.
    CHECK(warnings("produce { r; }").empty());
    CHECK(warnings("produce { r; e: Door at d.pos + (1, 0); }").empty());
    CHECK(warnings("produce { r; l: Lamp at d.pos; r -[Wall]- l; }").empty());
    CHECK(warnings("produce { l: Lamp at d.pos; }").empty());
    // Nor when no other rule keeps a door.
    auto alone = compile("node Room;\nnode Door;\nnode Lamp;\nedge Wall;\naxiom { r: Room; d: Door at (1, 0); r -[Wall]- d; }\n"
                         "rule Light { match { r: Room; d: Door; r -[Wall]- d; } produce { r; l: Lamp at d.pos; } }\n");
    CHECK(g2d::test::diagnosticLines(alone).empty());
}

TEST_CASE("declaration order: parameters, constants and functions see only earlier ones", "[sema][order]") {
    checkCases({
        {"constant used before its declaration", "const w = h * 2;\nconst h = 3;", "5:11: `h` is used before its declaration"},
        {"constant in its own definition", "const s = s + 1;", "5:11: constant `s` is used in its own definition"},
        {"function used before its declaration", "fn f(x: float) -> float = g(x);\nfn g(x: float) -> float = x;",
         "5:27: function `g` is used before its declaration"},
    });
    auto ok = compile(prelude() + "const k = 2;\nparam n: int = k;\nconst m = n + 1;\nrule R { match { x: P where x.w < m; } produce { x; } }");
    CHECK(firstError(ok).empty());
}

TEST_CASE("one mistake gives one error, not a cascade", "[sema][cascade]") {
    auto r = compile(prelude() + "const c = nosuch(1);\nconst d = (c, c);\n"
                                 "rule R { match { x: P; } let v = oops; produce { x at (v, c); } }");
    CHECK(g2d::test::diagnosticLines(r) ==
          std::vector<std::string>{"5:11: error: unknown function `nosuch`", "7:34: error: unknown name `oops`"});
}

TEST_CASE("fixes from the language reference review", "[sema][review]") {
    checkCases({
        {"randomness through a user function in a match",
         "fn coin() -> float = random();\nrule R { match { x: P where coin() < 0.5; } produce { x; } }",
         "6:29: function `coin` draws random numbers, which cannot be used in a match condition"},
        {"randomness through a user function in a default", "fn coin() -> float = random();\nnode Q { w: float = coin(); }",
         "6:21: function `coin` draws random numbers, which cannot be used in an attribute default"},
        {"repeated priority option", "priority 0 limit 2 limit 3;", "5:20: option given twice for priority 0"},
        {"an edge used as a value", "rule R { match { x: P; y: P; e: x -[E]-> y where e > 0; } produce { x; y; } }",
         "5:50: `e` is an edge, not a value; read one of its attributes instead"},
    });
    // A kept edge's endpoint may be kept by a later statement.
    auto later = compile(prelude() + "rule R { match { x: P; y: P; e: x -[E]-> y; } produce { x; e; m: P at (0, 0); y -[E]-> m; } }");
    CHECK(firstError(later).empty());
    // A daughter may create a node named like a node of a negative condition.
    auto nacName = compile(prelude() + "rule R { match { x: P; not { n: P; x -[E]-> n; } } produce { x; n: P at (1, 0); x -[E]-> n; } }");
    CHECK(firstError(nacName).empty());
    // Kind styles read the element's own facts.
    auto facts = compile(prelude() + "node Q { style { r = pos.x + age; } }");
    CHECK(firstError(facts).empty());
    // `x.w > 1 and false` can never hold.
    auto never = compile(prelude() + "rule R { match { x: P where x.w > 1 and false; } produce { x { w = 0 }; } }");
    REQUIRE(never.program);
    CHECK(g2d::test::diagnosticLines(never) ==
          std::vector<std::string>{"5:6: warning: rule `R` can never match: one of its conditions is always false"});
    // One mistake, one error.
    auto cascade1 = compile(prelude() + "rule R { match { x: P; } let int = 2; produce { x { w = int }; } }");
    CHECK(g2d::test::diagnosticLines(cascade1) == std::vector<std::string>{"5:30: error: `int` would hide the built-in `int`"});
    auto cascade2 = compile(prelude() + "rule R { match { x: Q; } produce { x; } }");
    CHECK(g2d::test::diagnosticLines(cascade2) == std::vector<std::string>{"5:21: error: unknown node kind `Q`"});
}

TEST_CASE("an unknown edge kind is reported once, not again at each use", "[sema][names]") {
    auto r = compile(prelude() + "rule R { match { a: P; b: P; old: a -[Q]-> b where old.n > 0; } produce { a; b; c: P at a.pos; a -[E { n = old.n }]-> c; } }");
    const auto lines = g2d::test::diagnosticLines(r);
    REQUIRE(lines.size() == 1);
    CHECK(lines[0] == "5:39: error: unknown edge kind `Q`");
}

TEST_CASE("faces in the axiom, matches and daughters: kinds, corners, names", "[sema][faces]") {
    const std::string kinds = "node P;\nedge E;\nface F { w: float = 1; }\n";   // 3 lines
    const std::string nodes = "axiom { a: P at (0, 0); b: P at (1, 0); c: P at (1, 1); ";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {nodes + "F(a, b); }", "4:57: a face needs at least 3 corners, got 2"},
        {nodes + "F(a, b, a); }", "4:65: corner `a` appears twice: a face's corners are distinct nodes"},
        {nodes + "F(a, b, d); }", "4:65: corner `d` is not a node of the axiom"},
        {nodes + "e: a -[E]- b; F(a, b, e); }", "4:79: corner `e` is not a node"},
        {nodes + "P(a, b, c); }", "4:57: `P` is a node kind, but a face needs a face kind"},
        {nodes + "Q(a, b, c); }", "4:57: unknown face kind `Q`"},
        {nodes + "F(a, b, c) { v = 2 }; }", "4:70: face kind `F` has no attribute `v`"},
        {nodes + "f: F(a, b, c); f: F(a, b, c); }", "4:72: `f` is already declared in the axiom"},
        {nodes + "}\nrule R { match { x: P; y: P; z: P; F(x, y, z); } produce { x; y; z; } }",
         "5:36: name the matched face (`f: F(…)`): a daughter keeps it by name (`f;`) or deletes it"},
        {nodes + "}\nrule R { match { x: P; y: P; f: F(x, y); } produce { x; y; } }", "5:30: a face needs at least 3 corners, got 2"},
        {nodes + "}\nrule R { match { x: P; y: P; f: F(x, y, q); } produce { x; y; } }", "5:41: corner `q` is not a node of the match"},
        {nodes + "}\nrule R { match { x: P; y: P; z: P; not { F(x, y, q); } } produce { x; y; z; } }",
         "5:50: corner `q` is not a node of the match or this negative condition"},
        {nodes + "}\nrule R { match { f: F where f.v > 1; } produce { } }", "5:31: face kind `F` has no attribute `v`; its attributes: w"},
        {nodes + "}\nrule R { match { f: F; x: P; } produce { x; y: P at (0, 0); F(x, y, f); } }", "5:69: corner `f` is a face, not a node"},
        {nodes + "}\nrule R { match { f: F; } produce { f at (0, 0); } }", "5:36: `f` is a face of the match; keep it with `f;` or `f { … };`"},
        {nodes + "}\nrule R { match { f: F @ (1, 1); } produce { f; } }",
         "5:18: a matched face takes no position, sketch or assignments; test it with `where`"},
        {nodes + "}\nrule R ordered { match { x: P @ (0, 0); y: P @ (1, 0); z: P @ (0, 1); f: F(x, y, z); } produce { } }",
         "5:71: an `ordered` rule cannot match faces: a face's corners are bound in cyclic order, whatever their positions"},
        {nodes + "}\nrule R { match { f: F; } produce { f: F(a, b, c); } }", "5:36: `f` is matched; a daughter's face needs a new name"},
        {nodes + "}\nrule R { match { x: P; y: P; } produce { x; y; F(x, y, x); } }",
         "5:56: corner `x` appears twice: a face's corners are distinct nodes"},
        {nodes + "}\nrule R { match { x: P; y: P; e: x -[E]- y; } produce { x; y; F(x, y, e); } }",
         "5:70: corner `e` is an edge, not a node"},
        {nodes + "}\nrule R { match { x: P; y: P; } produce { x; y; F(x, y, w); } }",
         "5:56: unknown name `w`: it is not a node of the match or this daughter"},
        {nodes + "}\nrule R { match { x: P; y: P; z: P; } produce { x; y; z; x: F(x, y, z); } }",
         "5:57: `x` appears twice in this daughter"},
        {nodes + "}\nrule R { match { x: P; y: P; z: P; } produce { y: F(x, y, z); } }",
         "5:48: `y` is matched; a daughter's face needs a new name"},
        {"face G directed;\naxiom { }",
         "4:8: expected `;`, `{` or a name, found `directed`; a face kind may be `oriented`, and only edge kinds are `directed` or "
         "`undirected`"},
    };
    for (const auto& [source, expected] : cases) {
        INFO(source);
        auto r = compile(kinds + source);
        CHECK(firstError(r) == expected);
        CHECK_FALSE(r.program.has_value());
    }
    auto ok = compile(kinds + nodes + "f: F(a, b, c) { w = 2 }; }\n"
                      "rule R { match { x: P; y: P; } produce { n: P at (0, 0); F(x, n, y) { w = x.pos.x }; } }");
    INFO(firstError(ok));
    REQUIRE(ok.program);
    REQUIRE(ok.program->axiom.faces.size() == 1);
    CHECK(ok.program->axiom.faces[0].corners == std::vector<int>{0, 1, 2});
    // A daughter's face: its corners are daughter nodes (naming a matched node keeps it).
    const auto& d = ok.program->rules[0].daughters[0];
    REQUIRE(d.faces.size() == 1);
    REQUIRE(d.faces[0].corners.size() == 3);
    CHECK(d.nodes[static_cast<std::size_t>(d.faces[0].corners[0])].motherNode == 0);
    CHECK(d.nodes[static_cast<std::size_t>(d.faces[0].corners[1])].name == "n");
    CHECK(d.nodes[static_cast<std::size_t>(d.faces[0].corners[2])].motherNode == 1);
    CHECK(d.deletedNodes.empty());
}

TEST_CASE("for loops over a face's sides and corners: located errors", "[sema][faces][loops]") {
    const std::string head = "node P { w: float = 0; }\nedge E;\nface F { w: float = 1; }\n"
                             "axiom { a: P at (0, 0); b: P at (1, 0); c: P at (1, 1); F(a, b, c); }\n";   // 4 lines
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"rule R { match { f: F; x: P; } produce { x; for (u, v) in x.sides { u -[E]- v; } } }",
         "5:59: `x` is not a face of the match: a loop walks a matched face"},
        {"rule R { match { f: F; } produce { for (u, v) in f.corners { u -[E]- v; } } }",
         "5:52: `for (u, v)` walks a face's sides: write `f.sides`"},
        {"rule R { match { f: F; } produce { for c in f.edges { } } }", "5:47: a loop walks `f.sides` or `f.corners`, not `f.edges`"},
        {"rule R { match { f: F; } produce { for c in f.corners { let k = 1; } } }",
         "5:57: a `let` inside `for` is not supported yet; compute the value in the loop's statements"},
        {"rule R { match { f: F; } produce { for c in f.corners { for d in f.corners { } } } }", "5:57: loops cannot be nested"},
        {"rule R { match { f: F; x: P; } produce { for c in f.corners { x; } } }",
         "5:63: a loop creates elements (`m: Kind at …;`); keep or change matched ones outside it"},
        {"rule R { match { f: F; } produce { for c in f.corners { m: P; c -[E]- m; } } }",
         "5:57: a node a loop creates needs a position: `at EXPR`"},
        {"rule R { match { f: F; } produce { for c in f.corners { m: P at c.pos; c -[E]- prev.z; } } }",
         "5:80: `prev.z`: `z` is not a node this loop creates"},
        {"rule R { match { f: F; x: P; } produce { x; m: P at x.pos; x -[E]- prev.m; } }",
         "5:68: `prev.m` names a node of a `for` loop's neighbouring turn: only inside `for`"},
        {"rule R { match { f: F; } produce { for (u, v) in f.sides { m: P at u.pos; n: P at m.pos; } } }",
         "5:83: `m` is created by this loop; expressions can read only the matched elements and the loop's corners"},
        {"rule R { match { f: F; } produce { for (u, v) in f.sides { m: P at u.pos { w = u.w }; } } }",
         "5:82: wildcard node `u` matches any kind, so it has no attribute `w`; only pos, age, generation, id, degree, in_degree, out_degree, faces can be read"},
        {"rule R { match { f: F; } produce { for (u, v) in f.sides { e: u -[E]- v; } } }",
         "5:60: elements a loop creates cannot be named (but its nodes)"},
    };
    for (const auto& [rule, expected] : cases) {
        INFO(rule);
        auto r = compile(head + rule);
        CHECK(firstError(r) == expected);
        CHECK_FALSE(r.program.has_value());
    }
}

TEST_CASE("warnings: an `intersect` rule whose new edge has no length beside a kept edge", "[sema][warnings][intersect]") {
    auto lines = [](const std::string& match, const std::string& produce) {
        auto r = compile(prelude() + "rule Bud intersect { match { " + match + " } produce { " + produce + " } }\nsequence { Bud; }\n");
        REQUIRE(r.program.has_value());
        return g2d::test::diagnosticLines(r);
    };
    const std::string edge = "a: P; t: P; s: a -[E]-> t;";
    CHECK(lines(edge, "s; c: P at t.pos; t -[E]-> c;") ==
          std::vector<std::string>{"5:72: warning: node `c` is placed at `t.pos`, so the new edge between them has no length and lies "
                                   "on edge `s` at `t`: rule `Bud`'s intersection test undoes every application"});
    CHECK(lines(edge, "s; c: P at t.pos + (0, 1); t -[E]-> c;").empty());   // a length: tested as it comes
    CHECK(lines("t: P;", "c: P at t.pos; t -[E]-> c;").empty());             // no edge of the match at `t` to lie on
}
