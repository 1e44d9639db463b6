#pragma once
// Tells the page when the edited file changes on disk (an editor beside the
// studio saved it): a thread looks at the file's version a few times a
// second, and each change is numbered; Server-Sent Events streams wait for
// the next number (cpp-httplib 0.11 has no WebSockets; SSE needs none).
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "studio/edited_file.hpp"

namespace g2d::studio {

struct FileChange {
    std::uint64_t number = 0;   // 0: the version the studio started with
    std::string version;
};

class FileWatch {
public:
    explicit FileWatch(const EditedFile& file, std::chrono::milliseconds every = std::chrono::milliseconds(200));
    ~FileWatch();   // stop() and join
    FileWatch(const FileWatch&) = delete;
    FileWatch& operator=(const FileWatch&) = delete;

    FileChange latest() const;
    // The first change numbered after `seen`, or nothing after `wait` or
    // once stopped.
    std::optional<FileChange> next(std::uint64_t seen, std::chrono::milliseconds wait) const;
    // Wakes every waiter for good (the server is shutting down).
    void stop();
    bool stopped() const;

private:
    void loop(std::chrono::milliseconds every, std::string seen);

    const EditedFile& file_;
    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;
    FileChange latest_;
    bool stopping_ = false;
    std::thread thread_;
};

}  // namespace g2d::studio
