#pragma once
// The progress bar of a seed batch on stderr: seeds done, failures, rate and
// time left. Shown only on a terminal, redrawn at most five times a second;
// clear() before printing anything else.
#include <chrono>
#include <cstddef>

namespace g2d::rt {

class BatchProgress {
public:
    BatchProgress(std::size_t total, bool wanted);
    ~BatchProgress() { clear(); }
    BatchProgress(const BatchProgress&) = delete;
    BatchProgress& operator=(const BatchProgress&) = delete;

    void update(std::size_t done, std::size_t failed);
    void clear();

private:
    std::size_t total_;
    bool enabled_, shown_ = false;
    std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace g2d::rt
