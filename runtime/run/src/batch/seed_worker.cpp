#include "g2d/seed_worker.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <string>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "g2d/seed_list.hpp"
#include "g2d/seed_rows.hpp"

namespace g2d::rt {

namespace {

std::optional<std::string> patterned(const std::optional<std::string>& pattern, std::uint64_t seed) {
    return pattern ? std::optional<std::string>(withSeed(*pattern, seed)) : std::nullopt;
}

// Sends what the last seed wrote on stderr (an in-memory file) and empties it.
std::string takeCapturedStderr() {
    std::fflush(stderr);
    struct stat st {};
    std::string text;
    if (::fstat(STDERR_FILENO, &st) == 0 && st.st_size > 0) {
        text.resize(static_cast<std::size_t>(st.st_size));
        const ssize_t n = ::pread(STDERR_FILENO, text.data(), text.size(), 0);
        text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    }
    if (::ftruncate(STDERR_FILENO, 0) != 0 || ::lseek(STDERR_FILENO, 0, SEEK_SET) < 0) text += "(a message may be missing)\n";
    return text;
}

SeedRow runOneSeed(const RunRequest& batch, GrammarRun& grammar, std::uint64_t seed) {
    SeedRow row;
    row.seed = seed;
    RunOutcome outcome;
    RunRequest request = seedRequest(batch, seed);
    request.outcome = &outcome;
    const auto start = std::chrono::steady_clock::now();
    try {
        row.status = runGrammar(request, grammar);
    } catch (const std::exception& e) {   // runGrammar reports its own errors; this is what escaped it (memory)
        std::fprintf(stderr, "%s: error: %s\n", batch.program.c_str(), e.what());
        row.status = 1;
    }
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    row.steps = outcome.steps;
    row.elements = outcome.elements;
    row.faces = outcome.faces;
    row.stopped = outcome.stopped.empty() ? "error" : outcome.stopped;
    // The derivation ended well but an output could not be written.
    if (row.status == 1 && (row.stopped == "terminal" || row.stopped == "step_limit")) row.stopped = "output_error";
    row.messages = takeCapturedStderr();
    return row;
}

}  // namespace

RunRequest seedRequest(const RunRequest& batch, std::uint64_t seed) {
    RunRequest r = batch;
    r.seeds.reset();
    r.jobs.reset();
    r.summaryOut.reset();
    r.outcome = nullptr;
    r.seed = seed;
    r.svgOut = patterned(batch.svgOut, seed);
    r.jsonOut = patterned(batch.jsonOut, seed);
    r.objOut = patterned(batch.objOut, seed);
    r.gltfOut = patterned(batch.gltfOut, seed);
    r.viewOut = patterned(batch.viewOut, seed);
    r.traceHtml = patterned(batch.traceHtml, seed);
    r.traceJson = patterned(batch.traceJson, seed);
    return r;
}

void runSeedWorker(const RunRequest& batch, GrammarRun& grammar, int seedsIn, int rowsOut) {
    const pid_t parent = ::getppid();
    // Should the parent die without stopping us (SIGKILL), stop too; the
    // SIGTERM handler removes unfinished outputs.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(1);
    const int capture = ::memfd_create("g2d-seed-messages", MFD_CLOEXEC);
    if (capture < 0 || ::dup2(capture, STDERR_FILENO) < 0) {
        std::fprintf(stderr, "%s: error: a worker could not catch its messages\n", batch.program.c_str());
        ::_exit(1);
    }
    ::close(capture);
    // Outputs are staged: the parent makes a group of them durable at once.
    std::vector<StagedFile> staged;
    setCommitStaging(&staged);
    std::uint64_t seed = 0;
    while (readFully(seedsIn, &seed, sizeof seed)) {
        staged.clear();
        SeedRow row = runOneSeed(batch, grammar, seed);
        row.staged = staged;
        if (!writeRow(rowsOut, row)) break;   // the parent is gone: the handler list still has them
        releaseStaged(staged);
    }
    for (const auto& f : staged)
        if (f.slot >= 0) ::unlink(f.temp.c_str());
    // _exit: the parent's objects (and buffered output) copied into this
    // process are not ours to destroy or flush.
    ::_exit(0);
}

}  // namespace g2d::rt
