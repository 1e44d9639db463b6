#pragma once
// The run procedure shared by `g2d run` and compiled grammars:
// RUN [-o OUT.svg|OUT.png [--dpi N | --width PX]] [--json OUT.json] [--obj OUT.obj [--obj-triangles]] [--gltf OUT.glb] [--view OUT.html] [--no-svg] [--svg-compact] [--precision N] [--embed-images] [--viewbox X0,Y0,X1,Y1] [--seed N] [-D NAME=VALUE]…
//     [--steps N] [--stats] [--max-elements N] [--timeout SECONDS] [--keep-partial] [--quiet]
//     [--seeds A..B [-j N] [--summary FILE]]
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "g2d/derive_grammar.hpp"
#include "g2d/grammar_run.hpp"

namespace g2d::rt {

struct RunOutcome;

struct RunRequest {
    std::string program = "g2d run";      // who reports usage and output errors ("g2d run", or a compiled program's name)
    std::string grammarFile;              // the .g2d file (messages, default output name)
    std::optional<std::string> svgOut;    // default: the grammar's name with .svg, in the current folder
    std::optional<std::string> jsonOut;
    std::optional<std::string> objOut;    // and its materials beside it, with .mtl (obj_writer.hpp)
    bool objTriangles = false;            // every OBJ face as triangles
    std::optional<std::string> gltfOut;   // binary glTF 2.0 (gltf_writer.hpp)
    std::optional<std::string> viewOut;   // the model in 3D, as a self-contained page (view_page.hpp)
    std::optional<std::string> viewFrom;  // 3D grammars: the SVG's view direction, "X,Y,Z" (projection.hpp)
    bool noSvg = false;
    bool svgCompact = false;              // runs of alike lines as one <path> each (svg_writer.hpp)
    std::optional<int> precision;         // SVG coordinates rounded to this many decimals
    bool embedImages = false;             // images as data: URIs, not links (image_links.hpp)
    std::optional<std::string> viewBox;   // "X0,Y0,X1,Y1": the SVG's viewBox, over the grammar's canvas (view_box.hpp)
    std::optional<double> dpi;            // PNG output (-o x.png): pixels per inch (default 96; the SVG's size is in cm)
    std::optional<int> width;             // PNG output: this many pixels wide instead (not with dpi)
    std::uint64_t seed = 1;
    std::vector<std::string> defines;     // NAME=VALUE
    std::optional<long long> steps;       // overrides the grammar's global limit
    bool stats = false;
    std::optional<long long> maxElements; // the runaway guard (default kDefaultMaxElements)
    std::optional<double> timeoutSeconds; // wall time of the derivation
    bool keepPartial = false;             // on a bound or a run-time error, still write the graph of the last completed step
    std::optional<std::string> traceHtml; // the derivation step by step, as a self-contained page
    std::optional<std::string> traceJson; // the same, as data
    bool verifyMatches = false;           // check incremental matching after every step (DerivationOptions)
    bool quiet = false;                   // no progress display on stderr
    // Many seeds (seed_batch.hpp): one derivation per seed of `seeds`, in
    // `jobs` worker processes, output names from the patterns ({seed}).
    std::optional<std::string> seeds;     // "1..1000", "1,5,9..12"
    std::optional<int> jobs;              // default: the cores this process may use
    std::optional<std::string> summaryOut;// the summary's JSON lines (default: stdout)
    RunOutcome* outcome = nullptr;        // filled in after the derivation, when set (a batch's summary row)
};

// How a derivation ended, for a batch's summary row.
struct RunOutcome {
    long long steps = 0;                  // the last completed step
    std::size_t elements = 0;             // nodes + edges
    std::size_t faces = 0;
    std::string stopped;                  // as in the JSON output ("terminal", "max_elements", "error", …)
};

// Runs and writes the outputs. Returns the exit code: 0 done, 1 a run-time
// error, a resource bound hit (elements, time, the default step limit when
// the grammar sets none) or an unwritable output, 2 bad arguments. Messages
// go to stderr, `--stats` to stdout. Outputs are written whole or not at
// all; after an error only with `keepPartial` (the last completed step, and
// the JSON's "stopped" says why).
int runGrammar(const RunRequest& request, GrammarRun& grammar);

}  // namespace g2d::rt
