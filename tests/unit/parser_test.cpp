// The parser: source text to AST, and syntax errors in words.
#include <catch2/catch.hpp>

#include "parse/parser.hpp"

using namespace g2d;

namespace {

struct Parsed {
    SourceManager sm;
    Diagnostics diags;
    std::optional<ast::Program> program;
};

Parsed parse(const std::string& text) {
    Parsed p;
    FileId id = p.sm.add("t.g2d", text);
    p.program = parseFile(p.sm, id, p.diags);
    return p;
}

std::string firstMessage(const Parsed& p) {
    if (p.diags.all().empty()) return "";
    const auto& d = p.diags.all().front();
    return std::to_string(d.span.line) + ":" + std::to_string(d.span.col) + ": " + d.message;
}

}  // namespace

TEST_CASE("declarations become AST nodes", "[parser]") {
    auto p = parse("import \"lib.g2d\";\n"
                   "param n: int = 3;\n"
                   "const c: float = 1.5e2;\n"
                   "enum Label { A, B, }\n"
                   "fn f(x: float, y: vec2) -> vec2 = y * x;\n"
                   "node N { a: int = 1; style { tag = \"circle\"; r = 0.5; } }\n"
                   "edge E directed { }\n"
                   "edge U undirected;\n"
                   "limit 100;\n"
                   "priority 2 limit 5 parallel;\n"
                   "defs \"<filter id='f'/>\";\n");
    REQUIRE(p.program);
    const auto& d = p.program->decls;
    REQUIRE(d.size() == 11);
    CHECK(std::get<ast::ImportDecl>(d[0].decl).path == "lib.g2d");
    const auto& param = std::get<ast::ParamDecl>(d[1].decl);
    CHECK(param.name.name == "n");
    CHECK(param.type.name.name == "int");
    CHECK(std::get<ast::IntLit>(param.value->node).value == 3);
    CHECK(std::get<ast::FloatLit>(std::get<ast::ConstDecl>(d[2].decl).value->node).value == 150.0);
    CHECK(std::get<ast::EnumDecl>(d[3].decl).values.size() == 2);
    const auto& fn = std::get<ast::FnDecl>(d[4].decl);
    CHECK(fn.params.size() == 2);
    CHECK(fn.result.name.name == "vec2");
    const auto& node = std::get<ast::KindDecl>(d[5].decl);
    CHECK(node.cls == ast::KindDecl::Class::Node);
    CHECK(node.attrs.size() == 1);
    CHECK(node.style.size() == 2);
    CHECK(std::get<ast::KindDecl>(d[6].decl).directed == std::optional<bool>(true));
    CHECK(std::get<ast::KindDecl>(d[7].decl).directed == std::optional<bool>(false));
    const auto& prio = std::get<ast::PriorityDecl>(d[9].decl);
    CHECK(prio.priority == 2);
    CHECK(prio.parallel);
    CHECK(prio.limit != nullptr);
    CHECK(std::get<ast::DefsDecl>(d[10].decl).svg == "<filter id='f'/>");
}

TEST_CASE("rules: options, match, negative conditions, lets, daughters", "[parser]") {
    auto p = parse("rule Split priority -1 pick oldest ordered parallel limit n + 1 {\n"
                   "  match {\n"
                   "    s: Point @ (0, 0); e: Point @ (1, 0); w: *;\n"
                   "    old: s -[Seg]-> e where old.lod < 3;\n"
                   "    e <-[Seg]- w;\n"
                   "    s -[Link]- w;\n"
                   "    where s.pos.x < e.pos.x;\n"
                   "    not { x: Point; s -[Seg]-> x; }\n"
                   "  }\n"
                   "  let v = e.pos - s.pos;\n"
                   "  produce weight 2 { s; e at s.pos + v; p: Point at (1, 2) { style.fill = \"red\" }; s -[Seg{lod = 1}]-> p; }\n"
                   "  produce { }\n"
                   "}\n");
    REQUIRE(p.program);
    const auto& r = std::get<ast::RuleDecl>(p.program->decls[0].decl);
    CHECK(r.name.name == "Split");
    REQUIRE(r.options.size() == 5);
    CHECK(r.options[0].priority == -1);
    CHECK(r.options[1].pick.name == "oldest");
    CHECK(r.options[4].kind == ast::RuleOption::Kind::Limit);
    CHECK(r.options[4].limit != nullptr);
    REQUIRE(r.match.size() == 8);
    const auto& s = std::get<ast::NodeStmt>(std::get<ast::GraphStmt>(r.match[0].stmt).stmt);
    CHECK(s.kind->name == "Point");
    CHECK(s.sketch->x == 0.0);
    CHECK(std::get<ast::NodeStmt>(std::get<ast::GraphStmt>(r.match[2].stmt).stmt).wildcard);
    const auto& old = std::get<ast::EdgeStmt>(std::get<ast::GraphStmt>(r.match[3].stmt).stmt);
    CHECK(old.name->name == "old");
    CHECK(old.arrow == ast::EdgeStmt::Arrow::Forward);
    CHECK(old.where != nullptr);
    CHECK(std::get<ast::EdgeStmt>(std::get<ast::GraphStmt>(r.match[4].stmt).stmt).arrow ==
          ast::EdgeStmt::Arrow::Backward);
    CHECK(std::get<ast::EdgeStmt>(std::get<ast::GraphStmt>(r.match[5].stmt).stmt).arrow ==
          ast::EdgeStmt::Arrow::Undirected);
    CHECK(std::holds_alternative<ast::WhereStmt>(r.match[6].stmt));
    CHECK(std::get<ast::NacBlock>(r.match[7].stmt).body.size() == 2);
    REQUIRE(r.items.size() == 3);
    const auto& prod = std::get<ast::ProduceBlock>(r.items[1].item);
    CHECK(prod.weight != nullptr);
    REQUIRE(prod.body.size() == 4);
    const auto& pnode = std::get<ast::NodeStmt>(std::get<ast::GraphStmt>(prod.body[2].stmt).stmt);
    REQUIRE(pnode.assigns.size() == 1);
    CHECK(pnode.assigns[0].isStyle);
    CHECK(pnode.assigns[0].name.name == "fill");
}

TEST_CASE("command lists: named lists and repeats, nested", "[parser]") {
    auto p = parse("sequence Round { A; repeat 2 * n { B; repeat 3 { C; } } }\n"
                   "sequence { Round; repeat depth { Round; } }\n"
                   "compound K { match { a: P; } sequence { repeat n { A; } } }\n");
    REQUIRE(p.program);
    const auto& round = std::get<ast::SequenceDecl>(p.program->decls[0].decl);
    REQUIRE(round.name);
    CHECK(round.name->name == "Round");
    REQUIRE(round.items.size() == 2);
    CHECK(round.items[0].name.name == "A");
    CHECK(round.items[0].count == nullptr);
    const auto& outer = round.items[1];
    REQUIRE(outer.count);
    CHECK(std::holds_alternative<ast::Binary>(outer.count->node));
    REQUIRE(outer.body.size() == 2);
    CHECK(outer.body[0].name.name == "B");
    REQUIRE(outer.body[1].count);
    CHECK(outer.body[1].body.at(0).name.name == "C");
    const auto& main = std::get<ast::SequenceDecl>(p.program->decls[1].decl);
    CHECK_FALSE(main.name);
    CHECK(main.items.size() == 2);
    const auto& k = std::get<ast::CompoundDecl>(p.program->decls[2].decl);
    REQUIRE(k.body.items.size() == 1);
    CHECK(k.body.items[0].body.at(0).name.name == "A");
}

TEST_CASE("a face over a loop's turns: Kind(all t [reversed])", "[parser]") {
    auto p = parse("rule R { match { f: F; } produce { for c in f.corners { t: P at c.pos; } Top(all t); Base(all c reversed); Q(a, b, c); } }\n");
    REQUIRE(p.program);
    const auto& rule = std::get<ast::RuleDecl>(p.program->decls[0].decl);
    const auto& body = std::get<ast::ProduceBlock>(rule.items.at(0).item).body;
    REQUIRE(body.size() == 4);
    const auto& top = std::get<ast::FaceStmt>(std::get<ast::GraphStmt>(body[1].stmt).stmt);
    REQUIRE(top.ring);
    CHECK(top.ring->every.name == "all");
    CHECK(top.ring->node.name == "t");
    CHECK_FALSE(top.ring->order);
    CHECK(top.corners.empty());
    const auto& base = std::get<ast::FaceStmt>(std::get<ast::GraphStmt>(body[2].stmt).stmt);
    REQUIRE(base.ring);
    CHECK(base.ring->order->name == "reversed");
    const auto& q = std::get<ast::FaceStmt>(std::get<ast::GraphStmt>(body[3].stmt).stmt);
    CHECK_FALSE(q.ring);
    CHECK(q.corners.size() == 3);
}

TEST_CASE("a parameter's range: `1..10` is two ints and `..`, and `1.` is still a float", "[parser]") {
    auto p = parse("param d: int = 6 in 1..10 step 2;\n"
                   "param t: float = 0.5 in 0.25..-x;\n"
                   "const f = 1.;\n");
    REQUIRE(p.program);
    const auto& d = std::get<ast::ParamDecl>(p.program->decls[0].decl);
    REQUIRE(d.range);
    CHECK(std::get<ast::IntLit>(d.range->lower->node).value == 1);
    CHECK(std::get<ast::IntLit>(d.range->upper->node).value == 10);
    REQUIRE(d.range->stepWord);
    CHECK(d.range->stepWord->name == "step");
    CHECK(std::get<ast::IntLit>(d.range->step->node).value == 2);
    CHECK(d.range->span.col == 18);   // from `in`, for the errors about the whole range
    const auto& t = std::get<ast::ParamDecl>(p.program->decls[1].decl);
    REQUIRE(t.range);
    CHECK(std::get<ast::FloatLit>(t.range->lower->node).value == 0.25);
    CHECK(std::get<ast::Unary>(t.range->upper->node).op == ast::UnaryOp::Neg);
    CHECK_FALSE(t.range->step);
    CHECK(std::get<ast::FloatLit>(std::get<ast::ConstDecl>(p.program->decls[2].decl).value->node).value == 1.0);
}

TEST_CASE("expression precedence", "[parser]") {
    auto p = parse("const x = 1 + 2 * 3 < 4 and not a or b ? -c.d : e;");
    REQUIRE(p.program);
    const auto& e = *std::get<ast::ConstDecl>(p.program->decls[0].decl).value;
    const auto& cond = std::get<ast::Conditional>(e.node);
    const auto& orExpr = std::get<ast::Binary>(cond.cond->node);
    CHECK(orExpr.op == ast::BinaryOp::Or);
    const auto& andExpr = std::get<ast::Binary>(orExpr.lhs->node);
    CHECK(andExpr.op == ast::BinaryOp::And);
    const auto& lt = std::get<ast::Binary>(andExpr.lhs->node);
    CHECK(lt.op == ast::BinaryOp::Lt);
    const auto& add = std::get<ast::Binary>(lt.lhs->node);
    CHECK(add.op == ast::BinaryOp::Add);
    CHECK(std::get<ast::Binary>(add.rhs->node).op == ast::BinaryOp::Mul);
    CHECK(std::get<ast::Unary>(andExpr.rhs->node).op == ast::UnaryOp::Not);
    const auto& neg = std::get<ast::Unary>(cond.then->node);
    CHECK(neg.op == ast::UnaryOp::Neg);
    CHECK(std::holds_alternative<ast::Member>(neg.operand->node));
}

TEST_CASE("spans are 1-based lines and columns in characters", "[parser]") {
    auto p = parse("// é comment\nconst  ü = 1;\n");
    // Identifiers are ASCII, so `ü` is a stray character at column 8.
    CHECK(firstMessage(p) == "2:8: unexpected character `ü`");
    auto q = parse("/* ☃ */ const x = 1;");
    REQUIRE(q.program);
    const auto& c = std::get<ast::ConstDecl>(q.program->decls[0].decl);
    CHECK(c.name.span.line == 1);
    CHECK(c.name.span.col == 15);
}

TEST_CASE("syntax errors name the expected tokens in words", "[parser][errors]") {
    CHECK(firstMessage(parse("param n: int = 3\nnode P;")) == "1:17: expected `;` or `in`, found `node`");
    CHECK(firstMessage(parse("node P { a: int }")) == "1:17: expected `;` or `=`, found `}`");
    CHECK(firstMessage(parse("const x = ;")) == "1:11: expected an expression, found `;`");
    CHECK(firstMessage(parse("const s = \"abc;")) == "1:11: unterminated string (missing closing `\"`)");
    CHECK(firstMessage(parse("/* never closed")) == "1:1: unterminated comment (missing `*/`)");
    CHECK(firstMessage(parse("node P; $")) == "1:9: unexpected character `$`");
    CHECK(firstMessage(parse("rule R { produce { } }")) == "1:10: expected `match`, found `produce`");
    CHECK(firstMessage(parse("axiom { a: P at; }")) == "1:16: expected an expression, found `;`");
    CHECK(firstMessage(parse("edge E directed { } node")) == "1:25: expected a name, found end of file");
}
