// The interpreter fuzz target's oracle: which failures may end a run.
#include <catch2/catch.hpp>

#include <variant>

#include "fuzz_checks.hpp"
#include "interp/evaluator.hpp"
#include "interp/interpreted_run.hpp"
#include "test_helpers.hpp"

using namespace g2d;

TEST_CASE("only a bound or a located run-time error may end a run", "[fuzz]") {
    auto compiled = test::compile(test::prelude() + "rule R { match { a: P; } produce { a; } }\n");
    REQUIRE(compiled.program);
    interp::InterpretedRun run(*compiled.program, &compiled.sources);

    CHECK_FALSE(fuzz::unexpectedRunFailure(rt::RunawayError("time_limit", "ran past the time limit"), run));
    const Span where{0, 5, 1, 5, 5};   // the rule's line of the snippet
    CHECK_FALSE(fuzz::unexpectedRunFailure(interp::EvalError(where, "division by zero"), run));

    // Internal faults: what the evaluator throws on a value of the wrong type,
    // a logic error, and a checked operation's error that lost its place.
    CHECK(fuzz::unexpectedRunFailure(std::bad_variant_access(), run));
    CHECK(fuzz::unexpectedRunFailure(std::logic_error("no such rule"), run));
    CHECK(fuzz::unexpectedRunFailure(rt::OpError("integer overflow"), run));
    CHECK(fuzz::unexpectedRunFailure(interp::EvalError(Span{}, "nowhere"), run));
}
