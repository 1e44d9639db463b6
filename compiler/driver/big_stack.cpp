#include "driver/big_stack.hpp"

#include <pthread.h>

namespace g2d {

namespace {
struct Job {
    const std::function<int()>* work;
    int result = 0;
};

extern "C" void* runJob(void* arg) {
    auto* job = static_cast<Job*>(arg);
    job->result = (*job->work)();
    return nullptr;
}
}  // namespace

int runWithBigStack(const std::function<int()>& work, std::size_t bytes) {
    Job job{&work};
    pthread_attr_t attr;
    if (pthread_attr_init(&attr) != 0) return work();
    pthread_t thread;
    const bool started = pthread_attr_setstacksize(&attr, bytes) == 0 && pthread_create(&thread, &attr, runJob, &job) == 0;
    pthread_attr_destroy(&attr);
    if (!started) return work();
    pthread_join(thread, nullptr);
    return job.result;
}

}  // namespace g2d
