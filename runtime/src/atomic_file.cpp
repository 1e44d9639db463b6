#include "g2d/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace g2d::rt {

namespace {

// Temporary files still open, for the signal handler: fixed storage, since a
// handler may only call async-signal-safe functions (unlink, signal, raise).
constexpr int kSlots = 16;
char tempPaths[kSlots][4096];
std::atomic<bool> slotUsed[kSlots];

extern "C" void removeTempFilesAndDie(int sig) {
    for (int i = 0; i < kSlots; ++i)
        if (slotUsed[i].load()) ::unlink(tempPaths[i]);
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

int registerTemp(const std::string& path) {
    static const bool installed = [] {
        for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, removeTempFilesAndDie);
        return true;
    }();
    (void)installed;
    if (path.size() >= sizeof tempPaths[0]) return -1;
    for (int i = 0; i < kSlots; ++i) {
        if (slotUsed[i].load()) continue;
        std::memcpy(tempPaths[i], path.c_str(), path.size() + 1);
        slotUsed[i].store(true);
        return i;
    }
    return -1;
}

void unregisterTemp(int slot) {
    if (slot >= 0) slotUsed[slot].store(false);
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
    struct stat st {};
    if (::stat(path_.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        throw OutputError("cannot write `" + path_ + "`: it is a directory");
    temp_ = path_ + ".tmp-XXXXXX";
    std::vector<char> buf(temp_.begin(), temp_.end());
    buf.push_back('\0');
    fd_ = ::mkstemp(buf.data());
    if (fd_ < 0) throw OutputError("cannot write `" + path_ + "`: " + std::strerror(errno));
    temp_.assign(buf.data());
    slot_ = registerTemp(temp_);
}

AtomicFile::~AtomicFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(temp_.c_str());
    unregisterTemp(slot_);
}

void AtomicFile::commit(const std::string& contents) {
    std::size_t done = 0;
    while (done < contents.size()) {
        const ssize_t n = ::write(fd_, contents.data() + done, contents.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw OutputError("cannot write `" + path_ + "`: " + std::strerror(errno));
        }
        done += static_cast<std::size_t>(n);
    }
    // Files we create are readable like any other output (mkstemp makes them 0600).
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd_, 0666 & ~mask);
    if (::fsync(fd_) != 0 || ::close(fd_) != 0) {
        fd_ = -1;
        throw OutputError("cannot write `" + path_ + "`: " + std::strerror(errno));
    }
    fd_ = -1;
    if (::rename(temp_.c_str(), path_.c_str()) != 0)
        throw OutputError("cannot write `" + path_ + "`: " + std::strerror(errno));
    committed_ = true;
    unregisterTemp(slot_);
    slot_ = -1;
}

}  // namespace g2d::rt
