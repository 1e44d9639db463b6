#include "studio/file_watch.hpp"

#include <sys/stat.h>

namespace g2d::studio {

namespace {

// What stat() says of the file: when it is unchanged, so is the text (an
// 8 MiB grammar is not read five times a second for nothing).
std::string statSignature(const std::string& path) {
    struct stat st {};
    if (path.empty() || ::stat(path.c_str(), &st) != 0) return "none";
    return std::to_string(st.st_ino) + ":" + std::to_string(st.st_size) + ":" + std::to_string(st.st_mtim.tv_sec) + "." +
           std::to_string(st.st_mtim.tv_nsec) + ":" + std::to_string(st.st_ctim.tv_nsec);
}

}  // namespace

FileWatch::FileWatch(const EditedFile& file, std::chrono::milliseconds every) : file_(file) {
    std::string seen = statSignature(file_.path());   // before the read: a change between them is seen
    latest_.version = file_.read().version;
    thread_ = std::thread([this, every, seen] { loop(every, seen); });
}

FileWatch::~FileWatch() {
    stop();
    thread_.join();
}

void FileWatch::loop(std::chrono::milliseconds every, std::string seen) {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!changed_.wait_for(lock, every, [this] { return stopping_; })) {
        const std::string now = statSignature(file_.path());
        if (now == seen) continue;
        seen = now;
        lock.unlock();
        // The version is the text's: a file touched but not changed is no change.
        const std::string version = file_.read().version;
        lock.lock();
        if (version != latest_.version) {
            latest_ = {latest_.number + 1, version};
            changed_.notify_all();
        }
    }
}

FileChange FileWatch::latest() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return latest_;
}

std::optional<FileChange> FileWatch::next(std::uint64_t seen, std::chrono::milliseconds wait) const {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!changed_.wait_for(lock, wait, [&] { return stopping_ || latest_.number > seen; }) || stopping_) return std::nullopt;
    return latest_;
}

void FileWatch::stop() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
}

bool FileWatch::stopped() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return stopping_;
}

}  // namespace g2d::studio
