// The C++ embedding API (g2d/grammar.hpp) on an interpreted run: attributes
// are read by the element's own class, faces included (a face's kind is
// not the node kind of the same id); the read-only GraphView.
#include <catch2/catch.hpp>

#include "g2d/grammar.hpp"
#include "interp/interpreted_run.hpp"
#include "test_helpers.hpp"

using namespace g2d;

TEST_CASE("Grammar::attribute reads nodes', edges' and faces' attributes by their own kinds", "[embedding]") {
    const CompileResult compiled = test::compile(R"(
node Dot { mass: int = 1; }
node Other { colour: string = "red"; }
edge Line { n: int = 3; }
face Room { tag: int = 7; size: float = 2.5; }
axiom {
    o: Other at (5, 5);
    a: Dot at (0, 0) { mass = 4 }; b: Dot at (1, 0); c: Dot at (0, 1);
    a -[Line]- b;
    r: Room(a, b, c) { size = 9 };
}
)");
    REQUIRE(compiled.program);
    Grammar grammar(std::make_unique<interp::InterpretedRun>(*compiled.program, nullptr), "rooms.g2d");
    grammar.derive();
    // Face 0 and node 0 share an id; node 0 (`o`, an Other) has no `size`.
    CHECK(std::get<long long>(grammar.attribute(rt::ElemClass::Face, 0, "tag")) == 7);
    CHECK(std::get<double>(grammar.attribute(rt::ElemClass::Face, 0, "size")) == 9.0);
    CHECK(std::get<std::string>(grammar.attribute(rt::ElemClass::Node, 0, "colour")) == "red");
    CHECK(std::get<long long>(grammar.attribute(rt::ElemClass::Node, 1, "mass")) == 4);
    CHECK(std::get<long long>(grammar.attribute(rt::ElemClass::Edge, 0, "n")) == 3);
    CHECK_THROWS_WITH(grammar.attribute(rt::ElemClass::Face, 0, "colour"), "kind `Room` has no attribute `colour`");
}

TEST_CASE("GraphView reads elements, kinds, positions, ends and corners", "[embedding]") {
    const CompileResult compiled = test::compile(R"(
node Dot;
node Other;
edge Line;
face Room;
axiom {
    o: Other at (5, 5);
    a: Dot at (0, 0); b: Dot at (1, 0); c: Dot at (0, 1);
    a -[Line]- b;
    Room(a, b, c);
}
rule Drop { match { o: Other; } produce { } }
)");
    REQUIRE(compiled.program);
    Grammar grammar(std::make_unique<interp::InterpretedRun>(*compiled.program, nullptr), "view.g2d");
    grammar.derive();
    const GraphView view = grammar.view();
    // `o` (node 0) was deleted: its id stays unused.
    CHECK(view.count(rt::ElemClass::Node) == 3);
    CHECK(view.capacity(rt::ElemClass::Node) == 4);
    CHECK(!view.alive(rt::ElemClass::Node, 0));
    CHECK(view.alive(rt::ElemClass::Node, 1));
    CHECK(view.kindName(rt::ElemClass::Node, 1) == "Dot");
    CHECK(view.kind(rt::ElemClass::Node, 1) == view.kind(rt::ElemClass::Node, 3));
    CHECK(view.position(2) == rt::vec3(1, 0, 0));
    CHECK(view.count(rt::ElemClass::Edge) == 1);
    CHECK(view.kindName(rt::ElemClass::Edge, 0) == "Line");
    CHECK((view.source(0) == 1 && view.target(0) == 2));
    CHECK(view.count(rt::ElemClass::Face) == 1);
    CHECK(view.kindName(rt::ElemClass::Face, 0) == "Room");
    CHECK(view.corners(0) == std::vector<GraphView::Id>{1, 2, 3});
}
