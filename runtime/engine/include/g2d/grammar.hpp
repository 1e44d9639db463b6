#pragma once
// The C++ API for programs that embed compiled grammars. They link the
// engine alone (g2d::engine: no librsvg, cairo or CLI11):
//
//   // CMakeLists.txt:  find_package(g2d)  g2d_add_grammar(app koch.g2d)
//   #include <g2d/grammar.hpp>
//   G2D_DECLARE_GRAMMAR(koch)                     // the grammar's factory
//   g2d::Grammar g(g2d_grammar_koch());
//   g.set("max_lod", "3");                        // parameters, as with -D
//   g.setSeed(42);
//   g.derive();                                   // or derive(steps)
//   g2d::GraphView graph = g.view();              // nodes, edges, faces, kinds, positions
//   g2d::rt::Value lod = g.attribute(g2d::rt::ElemClass::Edge, 0, "lod");
//   std::string svg = g.svg(), json = g.json(), obj = g.obj();   // the same bytes as g2d run
//
// This header includes little on purpose: values (value.hpp), element
// classes, a derivation's result, the read-only view (graph_view.hpp) and
// the interface a compiled grammar implements (grammar_run.hpp, which only
// declares the graph store and the rules; it must be complete here, as the
// factory's std::unique_ptr is destroyed where it is called). A program that needs the whole
// store (styles, ages, incidence lists) includes <g2d/graph.hpp> and reads
// graph().
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "g2d/derivation_result.hpp"
#include "g2d/elem_class.hpp"
#include "g2d/grammar_run.hpp"
#include "g2d/graph_view.hpp"
#include "g2d/value.hpp"

// Declares the factory that g2d_add_grammar(TARGET FILE NAME name) generates.
#define G2D_DECLARE_GRAMMAR(name) std::unique_ptr<g2d::rt::GrammarRun> g2d_grammar_##name();

namespace g2d {

class Grammar {
public:
    // `fileName` names the grammar in messages and in the JSON's "grammar".
    explicit Grammar(std::unique_ptr<rt::GrammarRun> run, std::string fileName = "grammar.g2d");

    std::vector<std::string> parameterNames() const;
    // Sets a parameter from text, as `-D NAME=VALUE`; throws std::invalid_argument.
    void set(const std::string& name, const std::string& value);
    void setSeed(std::uint64_t seed) { seed_ = seed; }

    // Derives from the axiom (again, if called twice). `steps` overrides the
    // grammar's global limit. Throws std::runtime_error on a run-time error,
    // with the grammar's source location in the message.
    rt::DerivationResult derive(std::optional<long long> steps = std::nullopt);

    // The graph as derived, read only (see graph_view.hpp).
    GraphView view() const;
    // An element's attribute by name; throws std::invalid_argument when its
    // kind has none of that name.
    rt::Value attribute(rt::ElemClass cls, std::uint32_t id, const std::string& name) const;
    // The whole store: include <g2d/graph.hpp> to use it.
    const rt::Graph& graph() const;

    // The outputs of `g2d run` with this seed and the same parameters, byte
    // for byte: the SVG (framed by the grammar's canvas, else fitted; a 3D
    // model seen from g2d run's default view), the JSON, the OBJ (naming
    // its materials file `mtlName` when one is given, as `--obj` names the
    // MTL it writes beside it) and that MTL.
    std::string svg();
    std::string json();
    std::string obj(const std::string& mtlName = {});
    std::string mtl();

private:
    std::unique_ptr<rt::GrammarRun> run_;
    std::string fileName_;
    std::vector<rt::Value> params_;
    std::uint64_t seed_ = 1;
    rt::DerivationResult last_;
};

}  // namespace g2d
