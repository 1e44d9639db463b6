#pragma once
// While a seed batch runs, SIGINT, SIGTERM and SIGHUP end it cleanly: the
// handler only notes the signal and wakes the batch's loop (wakeFd), which
// stops its workers (SIGTERM, then waits: each removes its unfinished
// outputs, see atomic_file.hpp) and then lets the signal act as before
// (remove this process's own temporary files, end it). The work is not done
// in the handler because `g2d run` works on a thread of its own (a big
// stack) while the handler may run on another, racing the loop that starts
// workers. A Ctrl-C on the terminal reaches the workers anyway; a signal sent
// to the parent alone (a scheduler, `timeout`) would not.
#include <sys/types.h>

namespace g2d::rt {

class WorkerInterrupts {
public:
    WorkerInterrupts();    // installs the handlers (an ignored signal stays ignored)
    ~WorkerInterrupts();   // puts the previous ones back
    WorkerInterrupts(const WorkerInterrupts&) = delete;
    WorkerInterrupts& operator=(const WorkerInterrupts&) = delete;

    // Readable once a signal came: poll it beside the workers' pipes.
    int wakeFd() const;
    // The signal that came, or 0.
    int pending() const;
    // Puts the previous handlers back and delivers `sig` to them (which ends the process).
    [[noreturn]] void resignal(int sig) const;

    // Around fork(): the signals wait (blocked) until the new worker has put
    // the previous handlers back (and closed the wake pipe), then reach it.
    void beforeFork() const;
    void afterForkInParent() const;
    void afterForkInWorker() const;
};

}  // namespace g2d::rt
