#pragma once
// The SVG, JSON and OBJ of a finished run, assembled in one place for the
// embedding API (Grammar::svg, json, obj) and for `g2d run` and compiled
// programs (run_driver.cpp), so that both write the same bytes. The caller
// picks the sinks (a file, or a string) and what only it knows: the frame,
// image links, the view of a 3D model, and why the derivation stopped.
#include <cstdint>
#include <string>

#include "g2d/derivation.hpp"
#include "g2d/grammar_run.hpp"
#include "g2d/projection.hpp"
#include "g2d/svg_writer.hpp"
#include "g2d/text_out.hpp"

namespace g2d::rt {

struct RunOutputs {
    // Where each output goes; none is written where this is null.
    TextOut* svg = nullptr;
    TextOut* json = nullptr;
    TextOut* obj = nullptr;
    TextOut* mtl = nullptr;                             // the OBJ's materials (obj_writer.hpp)
    std::string mtlName;                                // as the OBJ's `mtllib` names it
    bool objTriangles = false;                          // every OBJ face as triangles
    SvgOptions svgOptions;                              // its viewBox: --viewbox, else the canvas, else fitted
    ViewProjection view = viewFrom(kDefaultViewFrom);   // how the SVG shows a 3D model
    // The JSON's "graph" object.
    std::string grammarName;                            // the grammar file's name, without its folder
    std::uint64_t seed = 1;
    long long steps = 0;
    std::string stopped;                                // "terminal", "step_limit", or the bound that stopped it
};

// Writes the outputs `out` asks for, SVG first, then JSON, then OBJ; each
// sink is left to the caller to commit.
void writeRunOutputs(GrammarRun& grammar, const RunOutputs& out);

// How the JSON's "stopped" names a derivation that ended by itself.
const char* stopName(StopReason reason);

}  // namespace g2d::rt
