#include "g2d/worker_interrupts.hpp"

#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <unistd.h>

namespace g2d::rt {

namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
// What the handler touches: async-signal-safe storage only.
volatile sig_atomic_t pendingSignal = 0;
int wakePipe[2] = {-1, -1};
struct sigaction previous[3];

int indexOf(int sig) { return sig == SIGINT ? 0 : sig == SIGTERM ? 1 : 2; }

extern "C" void noteSignal(int sig) {
    pendingSignal = sig;
    const char byte = 1;
    (void)!::write(wakePipe[1], &byte, 1);   // non-blocking: one byte is enough
}

sigset_t handledSignals() {
    sigset_t set;
    sigemptyset(&set);
    for (int sig : kSignals) sigaddset(&set, sig);
    return set;
}

void restorePrevious() {
    for (int sig : kSignals) ::sigaction(sig, &previous[indexOf(sig)], nullptr);
}

}  // namespace

WorkerInterrupts::WorkerInterrupts() {
    pendingSignal = 0;
    if (::pipe2(wakePipe, O_CLOEXEC | O_NONBLOCK) != 0) wakePipe[0] = wakePipe[1] = -1;
    struct sigaction action {};
    action.sa_handler = noteSignal;
    action.sa_mask = handledSignals();
    for (int sig : kSignals) {
        ::sigaction(sig, &action, &previous[indexOf(sig)]);
        if (previous[indexOf(sig)].sa_handler == SIG_IGN) ::sigaction(sig, &previous[indexOf(sig)], nullptr);
    }
}

WorkerInterrupts::~WorkerInterrupts() {
    restorePrevious();
    for (int& fd : wakePipe) {
        if (fd >= 0) ::close(fd);
        fd = -1;
    }
}

int WorkerInterrupts::wakeFd() const { return wakePipe[0]; }

int WorkerInterrupts::pending() const { return pendingSignal; }

void WorkerInterrupts::resignal(int sig) const {
    restorePrevious();
    const sigset_t set = handledSignals();
    ::pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
    ::raise(sig);
    std::_Exit(128 + sig);   // the previous handler let the process live: end as a shell would report it
}

void WorkerInterrupts::beforeFork() const {
    const sigset_t set = handledSignals();
    ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
}

void WorkerInterrupts::afterForkInParent() const {
    const sigset_t set = handledSignals();
    ::pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
}

void WorkerInterrupts::afterForkInWorker() const {
    restorePrevious();
    for (int fd : wakePipe)
        if (fd >= 0) ::close(fd);
    const sigset_t set = handledSignals();
    ::pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
}

}  // namespace g2d::rt
