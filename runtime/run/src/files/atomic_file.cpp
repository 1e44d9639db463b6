#include "g2d/atomic_file.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace g2d::rt {

namespace {

// A long file's writeback is started every this many bytes, so that the
// disk works while the rest is made and the commit's fsync waits less.
constexpr long long kWritebackStride = 32LL << 20;

// Temporary files still open, for the signal handler: fixed storage, since a
// handler may only call async-signal-safe functions (unlink, signal, raise).
constexpr int kSlots = 64;

char tempPaths[kSlots][4096];
std::atomic<bool> slotUsed[kSlots];

extern "C" void removeTempFilesAndDie(int sig) {
    for (int i = 0; i < kSlots; ++i)
        if (slotUsed[i].load()) ::unlink(tempPaths[i]);
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

int registerTemp(const std::string& path) {
    installTempFileCleanup();
    if (path.size() >= sizeof tempPaths[0]) return -1;
    for (int i = 0; i < kSlots; ++i) {
        if (slotUsed[i].load()) continue;
        std::memcpy(tempPaths[i], path.c_str(), path.size() + 1);
        slotUsed[i].store(true);
        return i;
    }
    return -1;
}

}  // namespace

void installTempFileCleanup() {
    static const bool installed = [] {
        for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, removeTempFilesAndDie);
        return true;
    }();
    (void)installed;
}

namespace {

void unregisterTemp(int slot) {
    if (slot >= 0) slotUsed[slot].store(false);
}

// The file a chain of symbolic links names (even one that does not exist
// yet), so that rename() replaces it and not the link.
std::string followLinks(std::string path) {
    for (int hops = 0; hops < 40; ++hops) {
        struct stat lst {};
        if (::lstat(path.c_str(), &lst) != 0 || !S_ISLNK(lst.st_mode)) return path;
        std::vector<char> buf(4096);
        const ssize_t n = ::readlink(path.c_str(), buf.data(), buf.size() - 1);
        if (n <= 0) return path;
        std::string next(buf.data(), static_cast<std::size_t>(n));
        if (next[0] != '/') {
            const auto slash = path.rfind('/');
            if (slash != std::string::npos) next = path.substr(0, slash + 1) + next;
        }
        path = next;
    }
    return path;  // a loop: creating the temporary file next to it fails with ELOOP or succeeds harmlessly
}

std::vector<StagedFile>* staging = nullptr;

}  // namespace

void setCommitStaging(std::vector<StagedFile>* list) { staging = list; }

void releaseStaged(std::vector<StagedFile>& files) {
    for (auto& f : files) {
        unregisterTemp(f.slot);
        f.slot = -1;
    }
}

std::vector<std::string> placeStaged(const std::vector<StagedFile>& files) {
    std::vector<std::string> errors(files.size());
    std::vector<dev_t> synced;
    for (std::size_t i = 0; i < files.size(); ++i) {
        const int fd = ::open(files[i].temp.c_str(), O_RDONLY | O_CLOEXEC);
        struct stat st {};
        if (fd < 0 || ::fstat(fd, &st) != 0) {
            errors[i] = "cannot write `" + files[i].path + "`: " + std::strerror(errno);
        } else if (std::find(synced.begin(), synced.end(), st.st_dev) == synced.end()) {
            if (::syncfs(fd) != 0) errors[i] = "cannot write `" + files[i].path + "`: " + std::strerror(errno);
            else synced.push_back(st.st_dev);
        }
        if (fd >= 0) ::close(fd);
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
        // A file system that could not be synced keeps its files out of place.
        bool durable = errors[i].empty();
        if (durable && ::rename(files[i].temp.c_str(), files[i].target.c_str()) != 0)
            errors[i] = "cannot write `" + files[i].path + "`: " + std::strerror(errno);
        if (!errors[i].empty()) ::unlink(files[i].temp.c_str());
    }
    return errors;
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), target_(path_) {
    // A full file-size limit must fail a write, not kill the process.
    static const bool ignored = [] { return std::signal(SIGXFSZ, SIG_IGN) != SIG_ERR; }();
    (void)ignored;
    if (path_.empty()) throw OutputError("cannot write an output with an empty file name");
    struct stat st {};
    // /dev/stdout and the like name an open descriptor (maybe a redirected
    // regular file): written through, never replaced.
    const bool systemPath = path_.rfind("/dev/", 0) == 0 || path_.rfind("/proc/self/", 0) == 0;
    if (::stat(path_.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) throw OutputError("cannot write `" + path_ + "`: it is a directory");
        if (!S_ISREG(st.st_mode) || systemPath) {
            direct_ = true;
            fd_ = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC);
            if (fd_ < 0) throw OutputError("cannot write `" + path_ + "`: " + std::strerror(errno));
            return;
        }
    }
    target_ = followLinks(path_);
    temp_ = target_ + ".tmp-XXXXXX";
    std::vector<char> buf(temp_.begin(), temp_.end());
    buf.push_back('\0');
    fd_ = ::mkstemp(buf.data());
    if (fd_ < 0) throw OutputError("cannot write `" + path_ + "`: " + std::strerror(errno));
    temp_.assign(buf.data());
    slot_ = registerTemp(temp_);
}

AtomicFile::~AtomicFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_ && !direct_) ::unlink(temp_.c_str());
    unregisterTemp(slot_);
}

void AtomicFile::drain(const char* data, std::size_t size) {
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::write(fd_, data + done, size - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw OutputError("cannot write `" + path_ + "`: " + std::strerror(errno));
        }
        done += static_cast<std::size_t>(n);
    }
    written_ += static_cast<long long>(size);
    if (!direct_ && written_ - startedWriteback_ >= kWritebackStride) {
        // Only a hint, its errors ignored: the fsync of commit() is what counts.
        ::sync_file_range(fd_, startedWriteback_, written_ - startedWriteback_, SYNC_FILE_RANGE_WRITE);
        startedWriteback_ = written_;
    }
}

void AtomicFile::commit(const std::string& contents) {
    write(contents);
    commit();
}

void AtomicFile::commit() {
    flush();
    if (direct_) {
        const int fd = fd_;
        fd_ = -1;
        committed_ = true;
        if (::close(fd) != 0) throw OutputError("cannot write `" + path_ + "`: " + std::strerror(errno));
        return;
    }
    // Files we create are readable like any other output (mkstemp makes them 0600).
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd_, 0666 & ~mask);
    if (staging) {
        const int fd = fd_;
        fd_ = -1;
        if (::close(fd) != 0) throw OutputError("cannot write `" + path_ + "`: " + std::strerror(errno));
        staging->push_back({temp_, target_, path_, slot_});
        committed_ = true;   // the list's owner removes or places the file
        slot_ = -1;
        return;
    }
    if (::fsync(fd_) != 0 || ::close(fd_) != 0) {
        fd_ = -1;
        throw OutputError("cannot write `" + path_ + "`: " + std::strerror(errno));
    }
    fd_ = -1;
    if (::rename(temp_.c_str(), target_.c_str()) != 0)
        throw OutputError("cannot write `" + path_ + "`: " + std::strerror(errno));
    committed_ = true;
    unregisterTemp(slot_);
    slot_ = -1;
}

}  // namespace g2d::rt
