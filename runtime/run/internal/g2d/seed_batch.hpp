#pragma once
// Many seeds: `RUN --seeds 1..1000 -j N -o 'out/{seed}.svg'` runs one
// independent derivation per seed, each exactly as `RUN --seed K` would
// (same bytes), in N worker processes.
//
// Workers are fork()ed from the process that loaded the grammar, so the
// interpreter and generated code need no thread safety and share the loaded
// grammar copy-on-write; each worker reuses its GrammarRun seed after seed
// (start() rebuilds all run state). The parent hands out seeds one at a time
// (a slow seed does not hold up the others), collects each seed's summary
// row and prints the rows in seed order, whatever -j, as JSON lines on stdout
// or to --summary FILE. Messages of a seed's run are printed on stderr with
// a "seed K: " prefix. A progress bar is shown on stderr when it is a
// terminal (not with --quiet).
//
// Exit code: 0 when every seed succeeded, 1 when any failed (its row says
// how: "stopped" and "error"), 2 for bad arguments. SIGINT, SIGTERM and
// SIGHUP stop the workers (their unfinished outputs are removed) first.
#include "g2d/grammar_run.hpp"
#include "g2d/run_driver.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace g2d::rt {

inline constexpr int kMaxSeedJobs = 1024;   // -j's bound: worker processes at once

// --seeds, -j/--jobs and --summary (run_options.cpp); `seed` is --seed,
// which --seeds excludes.
void addSeedBatchOptions(CLI::App& app, RunRequest& request, CLI::Option* seed);

// Runs request.seeds; returns the exit code. Called by runGrammar.
int runSeedBatch(const RunRequest& request, GrammarRun& grammar);

}  // namespace g2d::rt
