#pragma once
// One thread that runs the studio's compiles and derivations in order, on
// a big stack as `g2d` runs its commands (deep grammars recurse deeply).
// One thread also keeps the front end single-threaded, as the LSP's is.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <pthread.h>

namespace g2d::studio {

class JobThread {
public:
    explicit JobThread(std::size_t stackBytes = std::size_t{1} << 30);
    ~JobThread();   // runs the jobs already posted, then joins
    JobThread(const JobThread&) = delete;
    JobThread& operator=(const JobThread&) = delete;

    void post(std::function<void()> job);

private:
    static void* loop(void* self);

    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::function<void()>> jobs_;
    bool stopping_ = false;
    pthread_t thread_{};
};

}  // namespace g2d::studio
