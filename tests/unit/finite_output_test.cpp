// No infinity or NaN reaches an output: the operations that make numbers
// check them (a located run-time error), and the writers refuse any left.
#include <catch2/catch.hpp>

#include <limits>

#include "g2d/json_writer.hpp"
#include "interp/run_program.hpp"
#include "test_helpers.hpp"

using namespace g2d;

TEST_CASE("random draws that overflow are run-time errors, not infinities", "[run][finite]") {
    for (const char* draw : {"uniform(-1e308, 1e308)", "normal(0, 1e308) * 1e10"}) {
        INFO(draw);
        auto c = test::compile(std::string("node P { f: float = 0; }\naxiom { a: P { f = ") + draw + " }; }\n");
        REQUIRE(c.program);
        bool failed = false;
        for (std::uint64_t seed = 1; seed <= 20 && !failed; ++seed) {
            try {
                interp::runProgram(*c.program, {}, seed, test::verified());
            } catch (const interp::EvalError& e) {
                CHECK(std::string(e.what()) == "the result is infinite");
                failed = true;
            }
        }
        CHECK(failed);
    }
}

TEST_CASE("the JSON writer never writes a non-finite number", "[json][finite]") {
    rt::Graph g({rt::KindInfo{rt::ElemClass::Node, false}});
    g.addNode(0, {0, 0}, 0);
    const rt::JsonSchema schema{{"P"}, {{"f"}}, {}};
    auto reading = [](double x) {
        return [x](rt::ElemClass, std::uint32_t, int) { return rt::Value{x}; };
    };
    CHECK_THAT(rt::writeJson(g, schema, {}, reading(1.5)), Catch::Contains("\"f\": 1.5"));
    CHECK_THROWS_WITH(rt::writeJson(g, schema, {}, reading(std::numeric_limits<double>::infinity())),
                      "node 0's attribute `f` is inf, which JSON cannot hold");
    CHECK_THROWS_WITH(rt::writeJson(g, schema, {}, reading(std::numeric_limits<double>::quiet_NaN())),
                      "node 0's attribute `f` is nan, which JSON cannot hold");
}
