// Incremental matching in whole runs: what a step's changes make the match
// sets search again, and what they leave alone.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <array>
#include <fstream>
#include <iterator>
#include <set>

#include "g2d/json_writer.hpp"
#include "g2d/svg_writer.hpp"
#include "interp/drawing.hpp"
#include "interp/interpreted_rules.hpp"
#include "interp/run_program.hpp"
#include "run_semantics_helpers.hpp"
#include "test_helpers.hpp"

using namespace g2d;
using g2d::test::compile;
using g2d::test::derive;
using g2d::test::countNodes;
using g2d::test::kindIndex;
using g2d::test::koch;

TEST_CASE("a negative condition not connected to the match sees changes anywhere", "[run][nac][incremental]") {
    // `not { b: B; }` holds only while no B exists anywhere: once the first
    // step makes one, the rule must stop matching, far from what changed.
    auto r = derive("node A; node B;\n"
                    "axiom { a: A at (0, 0); c: A at (5, 5); }\n"
                    "limit 10;\n"
                    "rule R { match { x: A; not { b: B; } } produce { x; b: B at (1, 1); } }\n");
    CHECK(r.run.derivation.steps == 1);
    CHECK(r.run.graph().nodeCount() == 3);
}

namespace {
// Counts how often each rule's matches are repaired after a step.
class CountingRules : public rt::RuleSet {
public:
    explicit CountingRules(rt::RuleSet& inner)
        : inner_(inner), repairs(inner.ruleCount(), 0), added(inner.ruleCount()), anchored(inner.ruleCount()) {}
    std::size_t ruleCount() const override { return inner_.ruleCount(); }
    const rt::RuleInfo& info(std::size_t rule) const override { return inner_.info(rule); }
    void findMatches(std::size_t rule, const rt::Graph& g, rt::MatchBuffer& out) override { inner_.findMatches(rule, g, out); }
    void findAnchored(std::size_t rule, const rt::Graph& g, int node, rt::NodeId host, rt::MatchBuffer& out,
                      rt::EdgeId newEdgesFrom) override {
        ++anchored[rule].back();
        inner_.findAnchored(rule, g, node, host, out, newEdgesFrom);
    }
    void repair(std::size_t rule, const rt::Graph& g, const rt::RepairArea& area, const rt::RepairAnchor* anchors, rt::MatchSet& set,
                rt::MatchBuffer& scratch) override {
        ++repairs[rule];
        const std::size_t before = set.size();   // after the broken matches were dropped
        anchored[rule].push_back(0);
        if (!forgetful) rt::RuleSet::repair(rule, g, area, anchors, set, scratch);   // the interpreter's (through findAnchored above)
        added[rule].push_back(static_cast<long long>(set.size() - before));
    }
    void writeSet(std::size_t rule, std::size_t daughter, rt::Match m, rt::WriteSet& out) const override {
        inner_.writeSet(rule, daughter, m, out);
    }
    void prepare(std::size_t rule, std::size_t daughter, rt::Match m, const rt::Graph& g, rt::Rng& rng, long long step) override {
        inner_.prepare(rule, daughter, m, g, rng, step);
    }
    void commit(rt::Graph& g, long long step) override { inner_.commit(g, step); }
    void discard() override { inner_.discard(); }

private:
    rt::RuleSet& inner_;

public:
    bool forgetful = false;   // repairs nothing: the sets go stale
    std::vector<long long> repairs;
    std::vector<std::vector<long long>> added;   // per rule, per repair: the matches it added
    std::vector<std::vector<long long>> anchored;   // per rule, per repair: its anchored searches
};
}  // namespace

TEST_CASE("match verification is an option of the derivation, and finds a stale set", "[run][incremental]") {
    // A rule set whose repair adds nothing loses the matches of the edges
    // each split creates. With verifyMatches the derivation says so at the
    // first step; without, it goes on with the stale set.
    const std::string src = "node P;\nedge E directed;\naxiom { a: P at (0, 0); b: P at (1, 0); a -[E]-> b; }\nlimit 6;\n"
                            "rule Split { match { s: P; e: P; old: s -[E]-> e; } produce { s; e; p: P at (0, 1); s -[E]-> p; p -[E]-> e; } }\n";
    auto compiled = test::compile(src);
    REQUIRE(compiled.program);
    for (const bool verify : {true, false}) {
        rt::Rng rng(3);
        auto [st, g] = test::startInterpreter(*compiled.program, rng);
        interp::InterpretedRules inner(st);
        CountingRules rules(inner);
        rules.forgetful = true;
        rt::DerivationOptions options;
        options.steps = 6;
        options.verifyMatches = verify;
        rt::DerivationResult result;
        if (verify) {
            CHECK_THROWS_WITH(rt::derive(g, rules, rng, options, result),
                              "incremental matching lost track of rule 0 after step 1: 0 matches kept, 2 found");
            CHECK(result.steps == 0);
        } else {
            rt::derive(g, rules, rng, options, result);
            CHECK(result.steps == 1);   // the only match was rewritten; the new ones were never found
        }
    }
}

TEST_CASE("a priority whose limit is used up is no longer kept up to date", "[run][limits]") {
    // Grow (priority 0, limit 5) would still match after its 5 steps; Walk
    // (priority 1) then runs 20 steps. Grow's matches are repaired only while
    // it can still apply, and the derivation is the same as without that.
    // (The Q nodes keep each step's changes below half the graph; at half or
    // more of a large graph, repair gives way to a full search.)
    std::string qs;
    for (int i = 0; i < 20; ++i) qs += " q" + std::to_string(i) + ": Q at (" + std::to_string(i) + ", 5);";
    const std::string src = "node P { n: int = 0; }\nnode Q;\nedge E directed;\naxiom { a: P at (0, 0);" + qs + " }\n"
                            "limit 25;\npriority 0 limit 5;\n"
                            "rule Grow priority 0 { match { a: P; } produce { a; b: P at (1, 0); a -[E]-> b; } }\n"
                            "rule Walk priority 1 { match { a: P; } produce { a { n = a.n + 1 }; } }\n";
    auto compiled = test::compile(src);
    REQUIRE(compiled.program);
    const auto& prog = *compiled.program;
    rt::Rng rng(7);
    auto [st, g] = test::startInterpreter(prog, rng);
    interp::InterpretedRules inner(st);
    CountingRules rules(inner);
    rt::DerivationOptions limits;
    limits.verifyMatches = true;
    limits.steps = 25;
    limits.perPriority[0] = 5;
    rt::DerivationResult result;
    rt::derive(g, rules, rng, limits, result);
    CHECK(result.steps == 25);
    CHECK(g.nodeCount() == 26);
    CHECK(rules.repairs[0] == 4);    // after Grow's steps 1-4; its 5th step spends the limit
    // After Grow's 5 steps (new P nodes); Walk's own steps write only an
    // attribute no condition reads, which leaves every set as it was.
    CHECK(rules.repairs[1] == 5);
    // The same derivation as the whole interpreter's run.
    auto whole = derive(src, 7);
    CHECK(whole.run.derivation.steps == 25);
    long long walked = 0;
    const int p = kindIndex(prog, "P");
    for (rt::NodeId n : whole.run.graph().nodesOfKind(p)) walked += std::get<long long>(whole.run.graph().nodeAttr(n, 0));
    CHECK(walked == 20);
}

TEST_CASE("edge changes alone keep the matches they do not break", "[run][incremental]") {
    // Splitting a→b of a path into a→p→b adds the two new edges' matches and
    // no other: the match of the next edge b→c, whose source b only saw its
    // edges change, stays in the set instead of being dropped and found again.
    std::string qs;
    for (int i = 0; i < 20; ++i) qs += " q" + std::to_string(i) + ": Q at (" + std::to_string(i) + ", 5);";
    const std::string src = "node P; node Q;\nedge E directed;\n"
                            "axiom { a: P at (0, 0); b: P at (1, 0); c: P at (2, 0); d: P at (3, 0); a -[E]-> b; b -[E]-> c; c -[E]-> d;" +
                            qs + " }\nlimit 12;\n"
                            "rule Split { match { s: P; e: P; old: s -[E]-> e; } produce { s; e; p: P at (0, 1); s -[E]-> p; p -[E]-> e; } }\n";
    auto compiled = test::compile(src);
    REQUIRE(compiled.program);
    rt::Rng rng(3);
    auto [st, g] = test::startInterpreter(*compiled.program, rng);
    interp::InterpretedRules inner(st);
    CountingRules rules(inner);
    rt::DerivationOptions limits;
    limits.verifyMatches = true;
    limits.steps = 12;
    rt::DerivationResult result;
    rt::derive(g, rules, rng, limits, result);
    CHECK(result.steps == 12);
    CHECK(g.edgeCount() == 15);
    CHECK(rules.added[0] == std::vector<long long>(12, 2));
    // Two anchored searches per step: from s (its outgoing edges changed)
    // at pattern node s, which reads outgoing edges, and from the new node p
    // at s. Not from e: only its incoming edges changed, which s does not
    // read and e reads none of (ir::Rule::readDirections). Not from p at e:
    // every match binding p binds a new edge, whose source is searched at
    // s, which adds it (ir::Rule::newHostAddsNothing).
    CHECK(rules.anchored[0] == std::vector<long long>(12, 2));
    // A second derivation on the same graph counts its steps from 1 again,
    // so edge ages do not tell its new edges: they are told by id.
    rules.added[0].clear();
    rt::DerivationResult again;
    rt::derive(g, rules, rng, limits, again);
    CHECK(again.steps == 12);
    CHECK(g.edgeCount() == 27);
    CHECK(rules.added[0] == std::vector<long long>(12, 2));
}

TEST_CASE("a kept edge whose attribute changes is matched again", "[run][incremental]") {
    // Count raises w on the one edge; Done needs w == 3. Only the edge's
    // attribute changes, never a node: its ends must still be searched again.
    auto r = derive("node P { done: bool = false; }\nedge E directed { w: int = 0; }\n"
                    "axiom { a: P at (0, 0); b: P at (1, 0); a -[E]-> b; }\nlimit 10;\n"
                    "rule Count priority 1 { match { a: P; b: P; e: a -[E]-> b where e.w < 3; } produce { a; b; e { w = e.w + 1 }; } }\n"
                    "rule Done { match { a: P where not a.done; b: P; e: a -[E]-> b where e.w == 3; } produce { a { done = true }; b; e; } }\n");
    CHECK(r.run.derivation.steps == 4);
    CHECK(r.run.derivation.stopped == rt::StopReason::Terminal);
    CHECK(std::get<bool>(r.run.graph().nodeAttr(0, 0)));
}

TEST_CASE("a kept edge moved to other ends is matched there", "[run][incremental]") {
    // Move swings x's edge from a over to b; Seen then needs an edge into b.
    auto r = derive("node P { seen: bool = false; }\nnode X;\nedge E directed;\n"
                    "axiom { a: P at (0, 0); b: P at (1, 0); x: X at (0, 1); x -[E]-> a; a -[E]-> b; }\nlimit 10;\n"
                    "rule Move priority 1 { match { x: X; a: P; b: P; e: x -[E]-> a; f: a -[E]-> b; } produce { x; a; b; f; e: x -[E]-> b; } }\n"
                    "rule Seen { match { x: X; b: P where not b.seen and b.id == 1; e: x -[E]-> b; } produce { x; b { seen = true }; e; } }\n");
    CHECK(r.run.derivation.steps == 2);
    CHECK(r.run.derivation.stopped == rt::StopReason::Terminal);
    CHECK(std::get<bool>(r.run.graph().nodeAttr(1, 0)));
}

TEST_CASE("a node lacking an edge kind its pattern node needs is not searched", "[run][matching]") {
    // x's condition divides by zero wherever it is evaluated; it is evaluated
    // only at an A that has (or had) an E edge, which the match needs there.
    const std::string kinds = "node A { z: int = 0; }\nnode B;\nedge E directed;\nedge F directed;\n";
    const std::string rule = "rule R { match { x: A where 10 % x.z == 0; y: B; x -[E]-> y; } produce { x; y; } }\n";
    SECTION("its only edges are of another kind: no match, no error") {
        auto r = derive(kinds + "axiom { a: A; b: B; a -[F]-> b; }\n" + rule);
        CHECK(r.run.derivation.steps == 0);
    }
    SECTION("with an edge of the needed kind the condition is evaluated") {
        auto c = compile(kinds + "axiom { a: A; b: B; a -[F]-> b; b -[E]-> a; }\n" + rule);
        REQUIRE(c.program);
        CHECK_THROWS_WITH(interp::runProgram(*c.program, {}, 1, test::verified()), "division by zero");
    }
}

TEST_CASE("picks are guessed a step ahead on large match sets", "[run][lookahead][large]") {
    // 40,000 Koch splits (toward level 14) grow the set by about three
    // matches a step, so past 32,768 matches each step prefetches the records of the
    // picks it guesses for the next steps (pick_lookahead.hpp). The guesses
    // only prefetch, so the result is the same either way; what this checks
    // is that they are right: random picks are drawn by a copy of the
    // generator with the set's size guessed from its last growths; oldest
    // picks come from the lowest age groups in turn, ties drawn alike.
    std::string random = koch(), oldest = koch();
    random.replace(random.find("pick oldest"), 11, "");
    for (const auto& [source, leastHits] : {std::pair{random, 0.99}, std::pair{oldest, 0.99}}) {
        auto r = derive(source, 5, 40000, {{"max_lod", 14LL}}, /*verify=*/false);
        const auto& d = r.run.derivation;
        CHECK(d.steps == 40000);
        CHECK(r.run.graph().edgeCount() == 3 + 3 * 40000);
        INFO(d.lookaheadHits << " of " << d.lookaheadGuesses << " guesses right");
        CHECK(d.lookaheadGuesses > 20000);
        CHECK(static_cast<double>(d.lookaheadHits) >= leastHits * static_cast<double>(d.lookaheadGuesses));
    }
}
