#pragma once
// A worker process of a seed batch (seed_batch.hpp): runs the seeds the
// parent sends, one after another, each as runGrammar would alone.
#include <cstdint>

#include "g2d/grammar_run.hpp"
#include "g2d/run_driver.hpp"

namespace g2d::rt {

// The request for one seed of the batch: the output names made from the
// patterns, and no batch options.
RunRequest seedRequest(const RunRequest& batch, std::uint64_t seed);

// In a forked child: reads seeds (8 bytes each) from `seedsIn` until its
// end, runs each and writes its row (seed_rows.hpp) to `rowsOut`, then
// exits. The seed's messages (stderr) are caught into the row, so a
// worker's stderr is no terminal and its runs show no progress of their own.
[[noreturn]] void runSeedWorker(const RunRequest& batch, GrammarRun& grammar, int seedsIn, int rowsOut);

}  // namespace g2d::rt
