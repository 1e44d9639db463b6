#pragma once
// Output files appear whole or not at all: the text goes to a temporary file
// in the same folder, which is renamed over the target on commit(). Temporary
// files are removed on failure, and on SIGINT, SIGTERM and SIGHUP too.
// A symbolic link is followed (the file it names is replaced, not the link).
// A target that exists and is not a regular file (/dev/stdout, a pipe,
// /dev/null) is written directly: it cannot be replaced, and must not be.
// A full disk or a file-size limit (SIGXFSZ is ignored) fails the commit
// with the system's reason, leaving the target as it was.
// The text is written in pieces (TextOut::write: a fixed-size buffer, so an
// output of any size costs the same memory), then commit() makes it appear.
#include <stdexcept>
#include <string>
#include <vector>

#include "g2d/text_out.hpp"

namespace g2d::rt {

class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A file whose text is complete but not yet durable nor in place: a batch of
// many small files makes a group of them durable with one syncfs (an fsync
// each would serialise the workers on the file system's journal).
struct StagedFile {
    std::string temp, target, path;   // path: as the user gave it, for messages
    int slot = -1;                    // in the signal handler's list, until released
};

// While a list is set, commit() closes its temporary file without syncing
// and appends it to the list instead of renaming it (the file stays on the
// signal handler's list: see releaseStaged).
void setCommitStaging(std::vector<StagedFile>* staging);
// Takes staged files off the signal handler's list: their owner (the batch's
// parent) now removes them or puts them in place.
void releaseStaged(std::vector<StagedFile>& files);
// Makes staged files durable (one syncfs per file system) and renames each
// over its target. Returns one text per file: "" or what went wrong.
std::vector<std::string> placeStaged(const std::vector<StagedFile>& files);

// Installs the signal handlers that remove temporary files now (else the
// first AtomicFile does), so that a program handling SIGINT and SIGTERM
// itself (`g2d studio`) can install its own after them.
void installTempFileCleanup();

class AtomicFile final : public TextOut {
public:
    // Creates the temporary file now, so an unwritable target fails early.
    explicit AtomicFile(std::string path);
    ~AtomicFile() override;  // removes the temporary file unless committed

    // Makes the text written so far the file's contents.
    void commit();
    // Writes `contents`, then commits.
    void commit(const std::string& contents);
    const std::string& path() const { return path_; }

private:
    void drain(const char* data, std::size_t size) override;

    std::string path_, temp_, target_;   // target_: path_ with symbolic links resolved
    int fd_ = -1;
    bool direct_ = false;                // writing straight into a non-regular file
    int slot_ = -1;   // in the signal handler's list
    bool committed_ = false;
    long long written_ = 0, startedWriteback_ = 0;   // bytes: written, and handed to writeback
};

}  // namespace g2d::rt
