#pragma once
// Output files appear whole or not at all: the text goes to a temporary file
// in the same folder, which is renamed over the target on commit(). Temporary
// files are removed on failure, and on SIGINT, SIGTERM and SIGHUP too.
#include <stdexcept>
#include <string>

namespace g2d::rt {

class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class AtomicFile {
public:
    // Creates the temporary file now, so an unwritable target fails early.
    explicit AtomicFile(std::string path);
    ~AtomicFile();  // removes the temporary file unless committed
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    void commit(const std::string& contents);
    const std::string& path() const { return path_; }

private:
    std::string path_, temp_;
    int fd_ = -1;
    int slot_ = -1;   // in the signal handler's list
    bool committed_ = false;
};

}  // namespace g2d::rt
