// `rule R limit N`: at most N steps apply the rule; the others go on.
#include "run_semantics_helpers.hpp"

using namespace g2d;
using namespace g2d::test;

namespace {

const char* const kGrow = R"(
param n: int = 3;
node A;
node B;
edge E;
axiom { a: A at (0, 0); }
limit 20;
rule Grow limit n { match { a: A; } produce { a; b: A at a.pos + (1, 0); a -[E]- b; } }
rule Mark priority 1 limit 2 { match { a: A; } produce { a; b: B at a.pos + (0, 1); a -[E]- b; } }
)";

}  // namespace

TEST_CASE("a rule's limit stops it and lets the next priority run", "[run][limit]") {
    // Grow (priority 0) would match forever; after n steps Mark (priority 1)
    // runs twice (its own limit), then nothing applies.
    for (long long n : {0LL, 1LL, 3LL, 7LL}) {
        auto r = derive(kGrow, 1, std::nullopt, {{"n", rt::Value{n}}});
        INFO("n = " << n);
        CHECK(r.run.derivation.steps == n + 2);
        CHECK(countNodes(r.run.graph(), kindIndex(*r.compiled.program, "A")) == static_cast<std::size_t>(n + 1));
        CHECK(countNodes(r.run.graph(), kindIndex(*r.compiled.program, "B")) == 2);
        CHECK(r.run.derivation.stopped == rt::StopReason::Terminal);
    }
}

TEST_CASE("a parallel rule's step counts once against its limit", "[run][limit]") {
    auto r = derive(R"(
node A;
node B;
axiom { a: A at (0, 0); b: A at (1, 0); c: A at (2, 0); }
limit 10;
rule Each parallel limit 2 { match { a: A; } produce { a; b: B at a.pos + (0, 1); } }
)");
    CHECK(r.run.derivation.steps == 2);
    CHECK(countNodes(r.run.graph(), kindIndex(*r.compiled.program, "B")) == 6);
}

TEST_CASE("a rule's limit of literals and constants that is 0 is a warning", "[sema][limit]") {
    auto c = compile("node A;\naxiom { a: A; }\nconst none = 0;\nrule R limit none { match { a: A; } produce { a; b: A at (0, 0); } }\n");
    REQUIRE(c.program);
    REQUIRE(diagnosticLines(c).size() == 1);
    CHECK(diagnosticLines(c)[0] == "4:8: warning: rule `R` has `limit 0`: it never applies");
}
