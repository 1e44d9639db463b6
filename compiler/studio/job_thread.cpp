#include "studio/job_thread.hpp"

#include <stdexcept>

namespace g2d::studio {

JobThread::JobThread(std::size_t stackBytes) {
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, stackBytes);
    const int failed = pthread_create(&thread_, &attr, &JobThread::loop, this);
    pthread_attr_destroy(&attr);
    if (failed) throw std::runtime_error("cannot start the studio's worker thread");
}

JobThread::~JobThread() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    pthread_join(thread_, nullptr);
}

void JobThread::post(std::function<void()> job) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        jobs_.push_back(std::move(job));
    }
    wake_.notify_all();
}

void* JobThread::loop(void* self) {
    auto& t = *static_cast<JobThread*>(self);
    for (;;) {
        std::function<void()> job;
        {
            std::unique_lock<std::mutex> lock(t.mutex_);
            t.wake_.wait(lock, [&] { return t.stopping_ || !t.jobs_.empty(); });
            if (t.jobs_.empty()) return nullptr;
            job = std::move(t.jobs_.front());
            t.jobs_.pop_front();
        }
        job();   // jobs catch their own exceptions
    }
}

}  // namespace g2d::studio
