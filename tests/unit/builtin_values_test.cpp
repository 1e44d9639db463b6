// Built-ins' values where the definition matters (tests/cli/builtins_test.py
// checks that folding, the interpreter and generated code agree).
#include <catch2/catch.hpp>

#include "g2d/builtins.hpp"

using namespace g2d;

TEST_CASE("smoothstep is the cubic between its edges, flat outside, either way round", "[builtins]") {
    CHECK(rt::fn::smoothstep(0, 2, 0.5) == 0.15625);
    CHECK(rt::fn::smoothstep(2, 0, 0.5) == 0.84375);
    CHECK(rt::fn::smoothstep(0, 1, -1) == 0.0);
    CHECK(rt::fn::smoothstep(0, 1, 2) == 1.0);
    CHECK(rt::fn::smoothstep(-1e308, 1e308, 0) == 0.5);   // no overflow between far edges
    CHECK_THROWS_WITH(rt::fn::smoothstep(1, 1, 0.5), "smoothstep(1, 1, x): the edges are equal");
}
