// What semantic analysis hands to the back ends: the typed IR.
#include <catch2/catch.hpp>

#include <algorithm>

#include "lower/kind_effects.hpp"
#include "lower/rule_facts.hpp"
#include "lower/search_plan.hpp"
#include "sema/builtins.hpp"
#include "test_helpers.hpp"

using namespace g2d;
using g2d::test::compile;

namespace {

CompileResult compileExample(const std::string& name) {
    LoadOptions options;
    options.importDirs = {G2D_STDLIB_DIR};
    return compileFile(std::string(G2D_SOURCE_DIR) + "/examples/" + name, options);
}

}  // namespace

TEST_CASE("the Koch snowflake lowers to one rule with an unrolled search plan", "[ir]") {
    auto r = compileExample("koch_snowflake.g2d");
    REQUIRE(r.diags.all().empty());
    REQUIRE(r.program);
    const auto& p = *r.program;
    REQUIRE(p.params.size() == 1);
    CHECK(p.params[0].name == "max_lod");
    CHECK(std::get<long long>(p.params[0].defaultValue) == 4);
    REQUIRE(p.consts.size() == 1);
    REQUIRE(p.consts[0].folded);
    CHECK(std::get<double>(*p.consts[0].folded) == Approx(0.28867513459481287));
    CHECK(p.axiom.nodes.size() == 3);
    REQUIRE(p.axiom.edges.size() == 3);
    CHECK(p.axiom.edges[2].src == 2);
    CHECK(p.axiom.edges[2].dst == 0);
    REQUIRE(p.rules.size() == 1);
    const auto& rule = p.rules[0];
    CHECK(rule.pick == ir::Pick::Oldest);
    CHECK(rule.nodes.size() == 2);
    CHECK(rule.edges.size() == 1);
    CHECK(rule.lets.size() == 3);
    REQUIRE(rule.daughters.size() == 1);
    const auto& d = rule.daughters[0];
    CHECK(d.weight == std::optional<double>(1.0));
    CHECK(d.nodes.size() == 5);
    CHECK(d.edges.size() == 4);
    CHECK(d.deletedNodes.empty());
    CHECK(d.deletedEdges == std::vector<int>{0});
    CHECK(d.nodes[0].motherNode == 0);
    CHECK(d.nodes[2].motherNode == -1);
    CHECK(d.nodes[2].position.has_value());
    // Plan: scan s, walk the edge to e, then test `old.lod < max_lod`.
    const auto plan = lower::buildSearchPlan(rule.nodes, rule.edges, rule.faces, rule.conditions, 0, 0, 0);
    REQUIRE(plan.size() == 3);
    CHECK(plan[0].op == lower::PlanStep::Op::ScanNodes);
    CHECK(plan[0].node == 0);
    CHECK(plan[1].op == lower::PlanStep::Op::ExtendEdge);
    CHECK(plan[1].edge == 0);
    CHECK(plan[1].from == 0);
    CHECK(plan[1].node == 1);
    CHECK(plan[1].fromIsSource);
    CHECK(plan[2].op == lower::PlanStep::Op::Check);
    REQUIRE(rule.conditions.size() == 1);
    CHECK(rule.conditions[0].deps == std::vector<ir::ElemRef>{{ir::ElemClass::Edge, 0}});
}

TEST_CASE("the tree uses the standard library and enums", "[ir]") {
    auto r = compileExample("tree.g2d");
    REQUIRE(r.diags.all().empty());
    REQUIRE(r.program);
    CHECK(r.program->functions.size() == 1);
    CHECK(r.program->enums.size() == 1);
    CHECK(r.program->rules.size() == 2);
    REQUIRE(r.program->stepLimit);
    CHECK(std::get<long long>(r.program->stepLimit->value) == 200);
}

TEST_CASE("conditions are tested as soon as their elements are bound", "[ir][plan]") {
    auto r = compile(test::prelude() +
                     "rule R {\n"
                     "  match { x: P where x.w > 0; y: P; z: P; x -[E]-> y; y -[E]-> z; where x.w < z.w; where true; }\n"
                     "  produce { x; y; z; }\n"
                     "}\n");
    REQUIRE(r.program);
    const auto& rule = r.program->rules[0];
    const auto plan = lower::buildSearchPlan(rule.nodes, rule.edges, rule.faces, rule.conditions, 0, 0, 0);
    using Op = lower::PlanStep::Op;
    std::vector<Op> ops;
    for (const auto& s : plan) ops.push_back(s.op);
    // `true` needs nothing, x's own test follows the scan of x, the cross test follows z.
    CHECK(ops == std::vector<Op>{Op::Check, Op::ScanNodes, Op::Check, Op::ExtendEdge, Op::ExtendEdge, Op::Check});
    CHECK(plan[0].condition == 2);
    CHECK(plan[2].condition == 0);
    CHECK(plan[5].condition == 1);
}

TEST_CASE("mapping by name: kept, deleted, new, implicit keeps and wildcards", "[ir][mapping]") {
    auto r = compile(test::prelude() +
                     "rule R {\n"
                     "  match { x: P; y: P; w: *; e: x -[E]-> y; f: y -[U]- w; }\n"
                     "  produce { n: P at x.pos; n -[E]-> y; e: n -[E]-> y; }\n"
                     "}\n");
    REQUIRE(r.program);
    const auto& d = r.program->rules[0].daughters[0];
    // n (new), y (kept as an endpoint), w (wildcard, always kept).
    REQUIRE(d.nodes.size() == 3);
    CHECK(d.nodes[0].motherNode == -1);
    CHECK(d.nodes[1].motherNode == 1);
    CHECK(d.nodes[2].motherNode == 2);
    CHECK(d.deletedNodes == std::vector<int>{0});
    CHECK(d.deletedEdges == std::vector<int>{1});
    REQUIRE(d.edges.size() == 2);
    CHECK(d.edges[1].motherEdge == 0);  // e is kept and rewired to n → y
    CHECK(d.edges[1].src == 0);
}

TEST_CASE("each reading match node reads the edge lists of its pattern edges' directions", "[ir][incremental]") {
    // Each pattern edge is read from one end (readsIncidence); that end
    // reads only its outgoing list for a directed edge leaving it, only its
    // incoming list for one entering it, both for an undirected edge or a
    // loop, and both where it reads every edge (a degree, a negative condition).
    auto r = compile("node P;\nedge D directed;\nedge U;\naxiom { a: P at (0, 0); }\n"
                     "rule Out { match { s: P; t: P; d: s -[D]-> t; } produce { s; t; } }\n"
                     "rule In { match { s: P; t: P; u: P; d: s -[D]-> t; f: u -[D]-> t; } produce { s; t; u; } }\n"
                     "rule Both { match { s: P; t: P; x: s -[U]- t; } produce { s; t; } }\n"
                     "rule Loop { match { s: P; l: s -[D]-> s; } produce { s; } }\n"
                     "rule Degree { match { s: P where s.degree > 1; t: P; d: s -[D]-> t; } produce { s; t; } }\n");
    INFO(test::firstError(r));
    REQUIRE(r.program);
    const auto& rules = r.program->rules;
    REQUIRE(rules.size() == 5);
    const std::uint8_t out = rt::RepairArea::kOut, in = rt::RepairArea::kIn, both = out | in;
    auto directions = [&](std::size_t i) { return lower::ruleFacts(*r.program, rules[i]).info.readDirections; };
    CHECK(directions(0) == std::vector<std::uint8_t>{out, 0});
    CHECK(directions(1) == std::vector<std::uint8_t>{0, in, 0});   // t covers both edges
    CHECK(directions(2) == std::vector<std::uint8_t>{both, 0});
    CHECK(directions(3) == std::vector<std::uint8_t>{both});
    CHECK(directions(4) == std::vector<std::uint8_t>{both, 0});
}

TEST_CASE("each rule knows the kinds and attributes its matches read and each daughter changes", "[ir][incremental]") {
    auto r = compile(R"(
node A { v: int = 0; w: int = 0; }
node B;
node C;
edge E directed;
edge F directed;
edge U;
axiom { a: A; }
rule Grow { match { a: A; b: B; e: a -[E]-> b; } produce { a { v = 1 }; b; n: C at (0, 0); a -[F]-> n; } }
rule Keep { match { a: A; b: B; e: a -[E]-> b; } produce { a; b; e; } }
rule Move { match { b: B; } produce { b at (1, 1); } }
rule Rewire { match { a: A; b: B; e: a -[E]-> b; } produce { a; b; e: b -[E]-> a; } }
rule Count { match { c: C where c.degree > 1; } produce { } }
rule ReadsW { match { a: A where a.w > 0; } produce { a; } }
rule NacReadsV { match { b: B; not { a: A where a.v > 1; a -[E]-> b; } } produce { b; } }
rule Guard { match { x: *; b: B; x -[E]-> b; not { y: C; x -[U]- y; } } produce { x; b; } }
)");
    REQUIRE(r.program);
    const auto& p = *r.program;
    auto kind = [&](const std::string& name) {
        for (std::size_t k = 0; k < p.kinds.size(); ++k)
            if (p.kinds[k].name == name) return static_cast<int>(k);
        FAIL("no kind " << name);
        return -1;
    };
    auto kinds = [&](std::vector<std::string> names) {
        std::vector<int> out;
        for (const auto& n : names) out.push_back(kind(n));
        std::sort(out.begin(), out.end());
        return out;
    };
    auto rule = [&](const std::string& name) {
        for (const auto& rr : p.rules)
            if (rr.name == name) return lower::ruleFacts(p, rr).info;
        FAIL("no rule " << name);
        return rt::RuleInfo{};
    };
    // Grow: the deleted edge, the new node and edge; the kept node's new
    // value is a change of that attribute, not of its kind.
    CHECK(rule("Grow").readKinds == kinds({"A", "B", "E"}));
    CHECK_FALSE(rule("Grow").readsDegrees);
    CHECK(rule("Grow").readValues.empty());
    CHECK(rule("Grow").changedKinds[0] == kinds({"C", "E", "F"}));
    CHECK(rule("Grow").changedValues[0] == std::vector<long long>{lower::valueKey(kind("A"), 0)});
    // The attributes conditions read, in the match or a negative condition.
    CHECK(rule("ReadsW").readValues == std::vector<long long>{lower::valueKey(kind("A"), 1)});
    CHECK(rule("NacReadsV").readValues == std::vector<long long>{lower::valueKey(kind("A"), 0)});
    CHECK(rule("NacReadsV").readKinds == kinds({"A", "B", "E"}));
    // Keeping everything as it was changes nothing.
    CHECK(rule("Keep").changedKinds[0].empty());
    // A new position is a change of the node.
    CHECK(rule("Move").changedKinds[0] == kinds({"B"}));
    // A kept edge between other ends is a change of the edge.
    CHECK(rule("Rewire").changedKinds[0] == kinds({"E"}));
    // A degree counts every edge kind; deleting the node is a change of its kind.
    CHECK(rule("Count").readsDegrees);
    CHECK(rule("Count").readKinds == kinds({"C", "E", "F", "U"}));
    CHECK(rule("Count").changedKinds[0] == kinds({"C"}));
    CHECK(rule("Count").deletesNodes[0] == 1);
    // A wildcard reads every node kind; a negative condition's kinds are read too.
    CHECK(rule("Guard").readKinds == kinds({"A", "B", "C", "E", "U"}));
}

TEST_CASE("the checker's random built-ins are the runtime's", "[sema][builtins]") {
    // sema::drawsRandom keeps random draws out of constants and parameter
    // defaults; it asks the runtime's table (rt::BuiltinEntry::drawsRandom)
    // about one built-in of the name. Every name resolves to built-ins of one kind.
    const std::vector<std::pair<std::string, std::vector<ir::Type>>> calls = {
        {"random", {}}, {"uniform", {ir::kFloatType, ir::kFloatType}}, {"randint", {ir::kIntType, ir::kIntType}},
        {"choice", {ir::kIntType, ir::kIntType}}, {"normal", {ir::kFloatType, ir::kFloatType}},
        {"sin", {ir::kFloatType}}, {"min", {ir::kIntType, ir::kIntType}}, {"str", {ir::kIntType}},
        {"format", {ir::kStringType}}, {"int", {ir::kFloatType}}, {"lerp", {ir::kFloatType, ir::kFloatType, ir::kFloatType}}};
    ir::Program prog;
    for (const auto& [name, args] : calls) {
        INFO(name);
        const auto* info = sema::findBuiltin(name);
        REQUIRE(info);
        auto res = sema::resolveBuiltin(name, args, prog);
        REQUIRE(std::holds_alternative<sema::BuiltinResolution>(res));
        CHECK(sema::drawsRandom(*info) == rt::builtinEntry(std::get<sema::BuiltinResolution>(res).builtin).drawsRandom);
    }
    std::size_t random = 0;
    for (const auto& b : sema::builtinFunctions()) random += sema::drawsRandom(b);
    CHECK(random == 5);
}
