#include "g2d/batch_progress.hpp"

#include <cstdio>
#include <string>
#include <unistd.h>

namespace g2d::rt {

namespace {

std::string clock(double seconds) {
    const long long s = static_cast<long long>(seconds + 0.5);
    char buf[32];
    if (s >= 3600)
        std::snprintf(buf, sizeof buf, "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
    else
        std::snprintf(buf, sizeof buf, "%lld:%02lld", s / 60, s % 60);
    return buf;
}

}  // namespace

BatchProgress::BatchProgress(std::size_t total, bool wanted)
    : total_(total), enabled_(wanted && isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()), last_(start_) {}

void BatchProgress::update(std::size_t done, std::size_t failed) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (shown_ && now - last_ < std::chrono::milliseconds(200)) return;
    if (!shown_ && now - start_ < std::chrono::milliseconds(500)) return;   // short batches show nothing
    last_ = now;
    shown_ = true;
    const double secs = std::chrono::duration<double>(now - start_).count();
    const double rate = secs > 0 ? static_cast<double>(done) / secs : 0;
    constexpr int kWidth = 24;
    const int filled = total_ ? static_cast<int>(kWidth * done / total_) : kWidth;
    const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '.');
    const std::string left = rate > 0 ? clock(static_cast<double>(total_ - done) / rate) + " left" : "";
    std::fprintf(stderr, "\r  [%s] %zu/%zu seeds%s  |  %.1f seeds/s  |  %s   ", bar.c_str(), done, total_,
                 failed ? (", " + std::to_string(failed) + " failed").c_str() : "", rate, left.c_str());
}

void BatchProgress::clear() {
    if (!shown_) return;
    std::fprintf(stderr, "\r%100s\r", "");
    shown_ = false;
}

}  // namespace g2d::rt
