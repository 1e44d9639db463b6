#include "g2d/seed_batch.hpp"

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <optional>
#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <stdexcept>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "g2d/atomic_file.hpp"
#include "g2d/batch_progress.hpp"
#include "g2d/seed_list.hpp"
#include "g2d/seed_rows.hpp"
#include "g2d/seed_worker.hpp"
#include "g2d/worker_interrupts.hpp"

namespace g2d::rt {

namespace {

constexpr std::size_t kGroupFiles = 128;   // outputs made durable together

int usageError(const RunRequest& request, const std::string& message) {
    std::fprintf(stderr, "%s: error: %s\n", request.program.c_str(), message.c_str());
    return 2;
}

struct OutputPattern {
    std::string option;    // for messages: "-o", "--json", …
    std::string pattern;
};

std::vector<OutputPattern> outputPatterns(const RunRequest& r) {
    std::vector<OutputPattern> out;
    if (!r.noSvg) out.push_back({"-o", r.svgOut.value_or(std::filesystem::path(r.grammarFile).stem().string() + ".svg")});
    const std::pair<const char*, const std::optional<std::string>*> others[] = {
        {"--json", &r.jsonOut}, {"--obj", &r.objOut}, {"--gltf", &r.gltfOut}, {"--view", &r.viewOut}, {"--trace", &r.traceHtml}, {"--trace-json", &r.traceJson}};
    for (const auto& [option, path] : others)
        if (*path) out.push_back({option, **path});
    return out;
}

// Why the batch cannot run as asked, or "".
std::string batchArgumentError(const RunRequest& r, std::size_t seedCount) {
    if (r.stats) return "--stats does not go with --seeds: the summary has a line per seed (steps, elements, faces, seconds, stopped)";
    if (seedCount < 2) return "";
    for (const auto& [option, pattern] : outputPatterns(r)) {
        if (hasSeedPlaceholder(pattern)) continue;
        if (option == "-o" && !r.svgOut)
            return "every seed would write " + pattern + " (the default SVG name): give -o 'NAME-{seed}.svg' or --no-svg";
        return option + " " + pattern + ": every seed would write this file; put {seed} in the name (e.g. out/{seed}.svg)";
    }
    return "";
}

// Opens (and drops) the first seed's outputs and the summary, so that an
// unwritable path fails once, before any work, and not once per seed.
bool outputsWritable(const RunRequest& r, std::uint64_t firstSeed) {
    try {
        for (const auto& output : outputPatterns(r)) AtomicFile probe(withSeed(output.pattern, firstSeed));
        if (r.summaryOut) AtomicFile probe(*r.summaryOut);
    } catch (const OutputError& e) {
        std::fprintf(stderr, "%s: error: %s\n", r.program.c_str(), e.what());
        return false;
    }
    return true;
}

// The cores this process may run on (a scheduler's share, not the machine's).
int defaultJobs() {
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
    const long online = sysconf(_SC_NPROCESSORS_ONLN);
    return online > 0 ? static_cast<int>(online) : 1;
}

std::string withPrefix(const std::string& text, const std::string& prefix) {
    std::string out;
    std::size_t from = 0;
    while (from < text.size()) {
        const std::size_t end = std::min(text.find('\n', from), text.size());
        out += prefix + text.substr(from, end - from) + "\n";
        from = end + 1;
    }
    return out;
}

struct Worker {
    pid_t pid = -1;
    int seedsFd = -1;                     // the parent sends seeds (a socket: a dead worker is EPIPE, not SIGPIPE)
    int rowsFd = -1;                      // the parent reads rows
    std::optional<std::size_t> running;   // the index of the seed it runs
};

class Batch {
public:
    Batch(const RunRequest& request, GrammarRun& grammar, std::vector<std::uint64_t> seeds)
        : request_(request), grammar_(grammar), seeds_(std::move(seeds)), rows_(seeds_.size()),
          progress_(seeds_.size(), !request.quiet), rowsToTerminal_(!request.summaryOut && isatty(STDOUT_FILENO)) {}

    int run(int jobs) {
        workers_.resize(static_cast<std::size_t>(std::min<std::size_t>(static_cast<std::size_t>(jobs), seeds_.size())));
        for (auto& w : workers_) {
            if (!start(w)) return stopAll(1);
            giveNextSeed(w);
        }
        while (done_ < seeds_.size()) {
            std::vector<pollfd> fds{pollfd{interrupts_.wakeFd(), POLLIN, 0}};
            std::vector<Worker*> polled{nullptr};
            for (auto& w : workers_)
                if (w.running) {
                    fds.push_back(pollfd{w.rowsFd, POLLIN, 0});
                    polled.push_back(&w);
                }
            if (::poll(fds.data(), fds.size(), 250) < 0 && errno != EINTR) {
                std::fprintf(stderr, "%s: error: waiting for the workers: %s\n", request_.program.c_str(), std::strerror(errno));
                return stopAll(1);
            }
            for (std::size_t i = 1; i < fds.size() && !interrupted(); ++i) {
                if (fds[i].revents == 0) continue;
                if (const int code = collect(*polled[i])) return stopAll(code);
            }
            if (interrupted()) {
                stopAll(1);
                interrupts_.resignal(interrupts_.pending() ? interrupts_.pending() : interruptedBy_);
            }
            progress_.update(done_, failed_);
        }
        stopAll(0);
        return finish();
    }

private:
    bool start(Worker& w) {
        int seeds[2], rows[2];
        if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, seeds) != 0) return startFailed();
        if (::pipe2(rows, O_CLOEXEC) != 0) {
            ::close(seeds[0]);
            ::close(seeds[1]);
            return startFailed();
        }
        std::fflush(stdout);
        std::fflush(stderr);
        interrupts_.beforeFork();
        const pid_t pid = ::fork();
        if (pid < 0) {
            interrupts_.afterForkInParent();
            for (int fd : {seeds[0], seeds[1], rows[0], rows[1]}) ::close(fd);
            return startFailed();
        }
        if (pid == 0) {
            interrupts_.afterForkInWorker();
            // Only its own channels: a worker holding another's would keep it from seeing its end.
            for (const auto& other : workers_)
                for (int fd : {other.seedsFd, other.rowsFd})
                    if (fd >= 0) ::close(fd);
            ::close(seeds[0]);
            ::close(rows[0]);
            runSeedWorker(request_, grammar_, seeds[1], rows[1]);
        }
        ::close(seeds[1]);
        ::close(rows[1]);
        interrupts_.afterForkInParent();
        w = Worker{pid, seeds[0], rows[0], std::nullopt};
        return true;
    }

    bool startFailed() {
        std::fprintf(stderr, "%s: error: cannot start a worker process: %s\n", request_.program.c_str(), std::strerror(errno));
        return false;
    }

    // The next seed, or the end of its seeds (it then exits).
    void giveNextSeed(Worker& w) {
        if (next_ == seeds_.size()) {
            if (w.seedsFd >= 0) ::close(w.seedsFd);
            w.seedsFd = -1;
            return;
        }
        w.running = next_;
        const std::uint64_t seed = seeds_[next_++];
        // Should the worker be gone, its rows pipe ends and collect() reports the seed.
        ::send(w.seedsFd, &seed, sizeof seed, MSG_NOSIGNAL);
    }

    // Reads a finished seed's row; a worker that died is reaped and replaced.
    // Returns an exit code to stop the batch with, or 0.
    int collect(Worker& w) {
        std::optional<SeedRow> row = readRow(w.rowsFd);
        const std::size_t index = *w.running;
        w.running.reset();
        if (!row) {
            const std::string death = reap(w);
            if (interrupted()) return 0;   // not a crash: the batch is being stopped
            row = SeedRow{};
            row->seed = seeds_[index];
            row->status = 1;
            row->stopped = "crashed";
            row->messages = "the worker process running this seed died (" + death + ")\n";
            if (next_ < seeds_.size() && !start(w)) return 1;
        }
        if (row->status == 2) {   // bad arguments (a -D, --steps…): the same for every seed, so said once
            progress_.clear();
            std::fputs(row->messages.c_str(), stderr);
            return 2;
        }
        if (!row->messages.empty()) {
            progress_.clear();
            std::fputs(withPrefix(row->messages, "seed " + std::to_string(row->seed) + ": ").c_str(), stderr);
        }
        if (row->status != 0) {
            ++failed_;
            if (failedSeeds_.size() < 10) failedSeeds_.push_back(row->seed);
        }
        for (auto& f : row->staged) pending_.push_back({index, std::move(f)});
        row->staged.clear();
        rows_[index] = std::move(row);
        ++done_;
        if (w.pid > 0) giveNextSeed(w);
        if (pending_.size() >= kGroupFiles || done_ == seeds_.size() || groupIsOld()) placePending();
        printRowsInOrder();
        return 0;
    }

    // A group of seeds' outputs made durable and put in place at once. A
    // seed's line is printed once its outputs are in place.
    void placePending() {
        std::vector<StagedFile> files;
        for (const auto& p : pending_) files.push_back(p.file);
        const std::vector<std::string> errors = placeStaged(files);
        for (std::size_t i = 0; i < pending_.size(); ++i) {
            if (errors[i].empty()) continue;
            SeedRow& row = *rows_[pending_[i].index];
            progress_.clear();
            std::fprintf(stderr, "seed %llu: %s: error: %s\n", static_cast<unsigned long long>(row.seed),
                         request_.program.c_str(), errors[i].c_str());
            if (row.status == 0) {
                row.status = 1;
                row.stopped = "output_error";
                row.messages = request_.program + ": error: " + errors[i] + "\n" + row.messages;
                ++failed_;
                if (failedSeeds_.size() < 10) failedSeeds_.push_back(row.seed);
            }
        }
        pending_.clear();
        groupStart_ = std::chrono::steady_clock::now();
    }

    // Outputs wait at most this long for their group.
    bool groupIsOld() const { return std::chrono::steady_clock::now() - groupStart_ > std::chrono::milliseconds(500); }

    // Staged outputs of a batch that stops are removed (as unfinished ones are).
    void discardPending() {
        for (const auto& p : pending_) ::unlink(p.file.temp.c_str());
        pending_.clear();
    }

    std::string reap(Worker& w) {
        int status = 0;
        while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
        }
        for (int fd : {w.seedsFd, w.rowsFd})
            if (fd >= 0) ::close(fd);
        w = Worker{};
        // Killed as the user stops work (Ctrl-C reaches every process of the
        // job): the batch stops too, and is not a crash.
        if (WIFSIGNALED(status) && !stopping_)
            for (int sig : {SIGINT, SIGTERM, SIGHUP})
                if (WTERMSIG(status) == sig) interruptedBy_ = sig;
        if (WIFSIGNALED(status)) return std::string("signal ") + std::to_string(WTERMSIG(status)) + ", " + strsignal(WTERMSIG(status));
        return "exit status " + std::to_string(WEXITSTATUS(status));
    }

    void printRowsInOrder() {
        auto placed = [&](std::size_t i) {
            for (const auto& p : pending_)
                if (p.index == i) return false;
            return true;
        };
        for (; printed_ < rows_.size() && rows_[printed_] && placed(printed_); ++printed_) {
            const std::string line = summaryLine(*rows_[printed_]);
            if (request_.summaryOut) {
                summary_ += line;
                continue;
            }
            if (rowsToTerminal_) progress_.clear();
            std::fputs(line.c_str(), stdout);
        }
        std::fflush(stdout);
    }

    // Ends the workers still running (on an error: SIGTERM; they remove
    // their unfinished outputs) and waits for all. Returns `code`.
    int stopAll(int code) {
        stopping_ = true;
        if (code != 0) discardPending();
        for (auto& w : workers_) {
            if (w.pid <= 0) continue;
            if (code != 0) ::kill(w.pid, SIGTERM);
            if (w.seedsFd >= 0) ::close(w.seedsFd);
            w.seedsFd = -1;
            // Rows not yet read may name staged outputs: they go too.
            if (code != 0)
                while (const auto row = readRow(w.rowsFd))
                    for (const auto& f : row->staged) ::unlink(f.temp.c_str());
            reap(w);
        }
        progress_.clear();
        return code;
    }

    bool interrupted() const { return interrupts_.pending() != 0 || interruptedBy_ != 0; }

    int finish() {
        if (request_.summaryOut) {
            try {
                AtomicFile(*request_.summaryOut).commit(summary_);
            } catch (const OutputError& e) {
                std::fprintf(stderr, "%s: error: %s\n", request_.program.c_str(), e.what());
                return 1;
            }
        }
        if (failed_ == 0) return 0;
        std::string which;
        for (const auto seed : failedSeeds_) which += (which.empty() ? "" : ", ") + std::to_string(seed);
        if (failed_ > failedSeeds_.size()) which += ", …";
        std::fprintf(stderr, "%s: error: %zu of %zu seeds failed (%s); their summary lines say why\n", request_.program.c_str(),
                     failed_, seeds_.size(), which.c_str());
        return 1;
    }

    const RunRequest& request_;
    GrammarRun& grammar_;
    const std::vector<std::uint64_t> seeds_;
    std::vector<std::optional<SeedRow>> rows_;   // by the seed's index, until printed
    std::vector<Worker> workers_;
    WorkerInterrupts interrupts_;
    BatchProgress progress_;
    const bool rowsToTerminal_;
    std::size_t next_ = 0, done_ = 0, printed_ = 0, failed_ = 0;
    bool stopping_ = false;                      // our own SIGTERMs are no interruption
    int interruptedBy_ = 0;                      // a worker died of SIGINT, SIGTERM or SIGHUP
    std::vector<std::uint64_t> failedSeeds_;     // the first ten, for the closing message
    std::string summary_;                        // --summary's lines, written at the end
    struct Pending {
        std::size_t index;   // the seed's
        StagedFile file;
    };
    std::vector<Pending> pending_;               // staged outputs of finished seeds, oldest first
    std::chrono::steady_clock::time_point groupStart_ = std::chrono::steady_clock::now();
};

}  // namespace

int runSeedBatch(const RunRequest& request, GrammarRun& grammar) {
    std::vector<std::uint64_t> seeds;
    try {
        seeds = parseSeedList(*request.seeds);
    } catch (const std::invalid_argument& e) {
        return usageError(request, e.what());
    }
    if (request.jobs && (*request.jobs < 1 || *request.jobs > kMaxSeedJobs))
        return usageError(request, "-j must be between 1 and " + std::to_string(kMaxSeedJobs));
    if (std::string err = batchArgumentError(request, seeds.size()); !err.empty()) return usageError(request, err);
    if (!outputsWritable(request, seeds.front())) return 1;
    return Batch(request, grammar, std::move(seeds)).run(request.jobs.value_or(std::min(defaultJobs(), kMaxSeedJobs)));
}

}  // namespace g2d::rt
