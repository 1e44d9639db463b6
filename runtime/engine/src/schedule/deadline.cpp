#include "g2d/deadline.hpp"

#include <chrono>

namespace g2d::rt {

namespace detail {
std::atomic<bool> deadlinePassed{false};
void throwDeadlinePassed() { throw DeadlinePassed(); }
}  // namespace detail

namespace {
std::mutex watching;   // held while a watch starts or ends, and while interrupting
bool watched = false;
}  // namespace

void interruptDerivation() {
    std::lock_guard<std::mutex> lock(watching);
    if (watched) detail::deadlinePassed.store(true);
}

DeadlineWatch::DeadlineWatch(double seconds) {
    {
        std::lock_guard<std::mutex> lock(watching);
        watched = true;
        detail::deadlinePassed.store(false);
    }
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    watcher_ = std::thread([this, until] {
        std::unique_lock<std::mutex> lock(mutex_);
        if (!wake_.wait_until(lock, until, [this] { return done_; })) detail::deadlinePassed.store(true);
    });
}

DeadlineWatch::~DeadlineWatch() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        done_ = true;
    }
    wake_.notify_all();
    watcher_.join();
    std::lock_guard<std::mutex> lock(watching);
    watched = false;
    detail::deadlinePassed.store(false);
}

}  // namespace g2d::rt
