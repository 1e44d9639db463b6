#pragma once
// One seed's result in a batch: sent by the worker that ran it to the parent
// through a pipe, and printed by the parent as a JSON line of the summary.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "g2d/atomic_file.hpp"

namespace g2d::rt {

struct SeedRow {
    std::uint64_t seed = 0;
    int status = 0;             // runGrammar's exit code for this seed: 0 done, 1 failed, 2 bad arguments
    long long steps = 0;        // the last completed step
    std::uint64_t elements = 0; // nodes + edges at the end
    std::uint64_t faces = 0;    // faces at the end
    double seconds = 0;         // wall time of the seed: derivation and outputs
    std::string stopped;        // as in the JSON output's "stopped", or "error", "crashed"
    std::string messages;       // what the run printed on stderr (errors, notes)
    std::vector<StagedFile> staged;   // its outputs, written but not yet durable nor in place
};

// Whole rows over a pipe. writeRow returns false when the parent is gone;
// readRow returns nullopt at the end of the pipe (the worker exited or died,
// even halfway through a row).
bool writeRow(int fd, const SeedRow& row);
std::optional<SeedRow> readRow(int fd);

// Reading and writing whole buffers, past EINTR and short transfers.
bool writeFully(int fd, const void* data, std::size_t size);
bool readFully(int fd, void* data, std::size_t size);   // false at the end of the file

// The summary's line, with a newline: {"seed": …, "steps": …, "elements": …,
// "faces": …, "seconds": …, "stopped": "…"}, and "error" (the first message line) when the seed failed.
std::string summaryLine(const SeedRow& row);

}  // namespace g2d::rt
