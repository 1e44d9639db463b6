#pragma once
// The wall-time bound of a derivation (--timeout), seen even inside a step
// that never finishes (a chain of functions each calling the previous twice
// costs 2^n calls): a watchdog thread raises a flag at the deadline, the
// derivation checks it between steps, and every call of a grammar function
// checks it too (one relaxed atomic load), interpreted or compiled.
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace g2d::rt {

// Thrown inside a step when the deadline has passed; the derivation turns it
// into a RunawayError naming the step.
class DeadlinePassed : public std::runtime_error {
public:
    DeadlinePassed() : std::runtime_error("the time limit passed") {}
};

namespace detail {
extern std::atomic<bool> deadlinePassed;
[[noreturn]] void throwDeadlinePassed();
}  // namespace detail

inline bool deadlineHasPassed() { return detail::deadlinePassed.load(std::memory_order_relaxed); }
inline void checkDeadline() {
    if (deadlineHasPassed()) detail::throwDeadlinePassed();
}

// Raises the flag now if a DeadlineWatch is watching: the derivation in
// flight stops at its next check, as at its deadline (`g2d studio` cancels
// a run that a newer edit replaces). Without a watch it does nothing, so no
// raised flag is left for a later run's start.
void interruptDerivation();

// Raises the flag `seconds` from now unless destroyed first (which lowers it).
class DeadlineWatch {
public:
    explicit DeadlineWatch(double seconds);
    ~DeadlineWatch();
    DeadlineWatch(const DeadlineWatch&) = delete;
    DeadlineWatch& operator=(const DeadlineWatch&) = delete;

private:
    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false;
    std::thread watcher_;
};

}  // namespace g2d::rt
