#pragma once
// The C++ API for programs that embed compiled grammars:
//
//   // CMakeLists.txt:  find_package(g2d)  g2d_add_grammar(app koch.g2d)
//   #include <g2d/grammar.hpp>
//   G2D_DECLARE_GRAMMAR(koch)                     // the grammar's factory
//   g2d::Grammar g(g2d_grammar_koch());
//   g.set("max_lod", "3");                        // parameters, as with -D
//   g.setSeed(42);
//   g.derive();                                   // or derive(steps)
//   const g2d::rt::Graph& graph = g.graph();      // nodes, edges, positions
//   std::string svg = g.svg(), json = g.json();   // the same bytes as g2d run
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "g2d/grammar_run.hpp"

// Declares the factory that g2d_add_grammar(TARGET FILE NAME name) generates.
#define G2D_DECLARE_GRAMMAR(name) std::unique_ptr<g2d::rt::GrammarRun> g2d_grammar_##name();

namespace g2d {

class Grammar {
public:
    explicit Grammar(std::unique_ptr<rt::GrammarRun> run, std::string fileName = "grammar.g2d");

    std::vector<std::string> parameterNames() const;
    // Sets a parameter from text, as `-D NAME=VALUE`; throws std::invalid_argument.
    void set(const std::string& name, const std::string& value);
    void setSeed(std::uint64_t seed) { seed_ = seed; }

    // Derives from the axiom (again, if called twice). `steps` overrides the
    // grammar's global limit. Throws std::runtime_error on a run-time error,
    // with the grammar's source location in the message.
    rt::DerivationResult derive(std::optional<long long> steps = std::nullopt);

    const rt::Graph& graph() const { return run_->graph(); }
    rt::Value attribute(rt::ElemClass cls, std::uint32_t id, const std::string& name) const;
    std::string svg();
    std::string json();

private:
    std::unique_ptr<rt::GrammarRun> run_;
    std::string fileName_;
    std::vector<rt::Value> params_;
    std::uint64_t seed_ = 1;
    rt::DerivationResult last_;
};

}  // namespace g2d
