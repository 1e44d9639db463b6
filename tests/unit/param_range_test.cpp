// A parameter's declared range (`in MIN..MAX [step STEP]`, docs/language.md
// §5.2): the interpreter's ParamSpec carries it as written (step only when
// written; bounds folded from constants), and values outside it are refused
// by the one reader of parameter values, in words that name the parameter.
#include <catch2/catch.hpp>

#include "g2d/grammar.hpp"
#include "interp/interpreted_run.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

const char* kRanged = R"(
const top = 5 * 2;
param depth: int = 6 in 1..top;
param tilt: float = 0.5 in 0..1 step 0.05;
param spin: float = 0 in -pi..pi;
param free: float = 3;
node P;
axiom { a: P at (depth * tilt + spin + free, 0); }
)";

}  // namespace

TEST_CASE("ParamSpec holds a parameter's range as its declaration gives it", "[params]") {
    const CompileResult compiled = test::compile(kRanged);
    REQUIRE(compiled.program);
    const auto specs = interp::paramSpecs(*compiled.program);
    REQUIRE(specs.size() == 4);
    CHECK(specs[0].min == 1.0);
    CHECK(specs[0].max == 10.0);
    CHECK_FALSE(specs[0].step);   // an int's step of 1 is the studio's to assume
    CHECK(specs[1].min == 0.0);
    CHECK(specs[1].max == 1.0);
    CHECK(specs[1].step == 0.05);
    CHECK(specs[2].min == -3.141592653589793);
    CHECK(specs[2].max == 3.141592653589793);
    CHECK_FALSE(specs[3].min);
    CHECK_FALSE(specs[3].max);
    CHECK_FALSE(specs[3].step);
}

TEST_CASE("A value outside the declared range is refused, the bounds themselves accepted", "[params]") {
    const CompileResult compiled = test::compile(kRanged);
    REQUIRE(compiled.program);
    const auto specs = interp::paramSpecs(*compiled.program);
    std::string why;
    CHECK(rt::parameterValue(specs[0], "1", why));
    CHECK(rt::parameterValue(specs[0], "10", why));
    CHECK_FALSE(rt::parameterValue(specs[0], "11", why));
    CHECK(why == "parameter `depth` must be from 1 to 10 (the range its declaration gives), not 11");
    CHECK_FALSE(rt::parameterValue(specs[1], "-0.25", why));
    CHECK(why == "parameter `tilt` must be from 0 to 1 (the range its declaration gives), not -0.25");
    CHECK_FALSE(rt::parameterValue(specs[0], "six", why));
    CHECK(why == "parameter `depth`: expected an int, got `six`");
    CHECK(rt::parameterValue(specs[3], "1e9", why));   // no range: any float

    // The embedding API reads values the same way.
    Grammar grammar(std::make_unique<interp::InterpretedRun>(*compiled.program, nullptr), "ranged.g2d");
    CHECK_NOTHROW(grammar.set("tilt", "1"));
    CHECK_THROWS_WITH(grammar.set("depth", "0"),
                      "parameter `depth` must be from 1 to 10 (the range its declaration gives), not 0");
}

TEST_CASE("Range errors are located at the part that is wrong", "[params]") {
    auto first = [](const std::string& decl) {
        return test::firstError(test::compile(decl + "\nnode P;\naxiom { a: P at (0, 0); }\n"));
    };
    CHECK(first("param d: int = 6 in 10..1;") == "1:18: the range 10..1 of parameter `d` is empty: its lower bound is above its upper bound");
    CHECK(first("param d: int = 0 in 1..10;") == "1:16: the default of parameter `d`, 0, is outside its range 1..10");
    CHECK(first("param t: float = 0.5 in 0..1 step -0.1;") == "1:35: the step of parameter `t` must be above 0, not -0.1");
    CHECK(first("param b: bool = true in 0..1;") == "1:22: a range applies to int and float parameters only; `b` is of type bool");
    // A range of one value is allowed; so is a float written as an int bound.
    CHECK(first("param d: int = 3 in 3..3;\nparam t: float = 1 in 0..2 step 1;") == "");
}
