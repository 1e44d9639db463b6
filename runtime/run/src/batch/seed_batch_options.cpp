// The command-line options of a seed batch (seed_batch.hpp).
#include <CLI/CLI.hpp>

#include "g2d/seed_batch.hpp"

namespace g2d::rt {

void addSeedBatchOptions(CLI::App& app, RunRequest& r, CLI::Option* seed) {
    CLI::Option* seeds =
        app.add_option_function<std::string>(
               "--seeds", [&r](const std::string& v) { r.seeds = v; },
               "Run one derivation per seed: A..B (inclusive), or a list like 1..100,250; output names need {seed}")
            ->type_name("LIST");
    seeds->excludes(seed);
    app.add_option_function<int>("-j,--jobs", [&r](int v) { r.jobs = v; },
                                 "--seeds: derivations run at once, in worker processes (default: the cores)")
        ->type_name("N")
        ->check(CLI::Range(1, kMaxSeedJobs))
        ->needs(seeds);
    app.add_option_function<std::string>("--summary", [&r](const std::string& v) { r.summaryOut = v; },
                                         "--seeds: write the summary's JSON lines (one per seed) to FILE, not stdout")
        ->type_name("FILE")
        ->needs(seeds);
}

}  // namespace g2d::rt
