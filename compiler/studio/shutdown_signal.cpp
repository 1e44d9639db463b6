#include "studio/shutdown_signal.hpp"

#include <csignal>
#include <stdexcept>
#include <unistd.h>

#include "g2d/atomic_file.hpp"

namespace g2d::studio {

namespace {

int pipeEnds[2] = {-1, -1};

extern "C" void signalled(int sig) {
    const char byte = static_cast<char>(sig);
    [[maybe_unused]] auto n = ::write(pipeEnds[1], &byte, 1);
}

}  // namespace

ShutdownSignal::ShutdownSignal(std::function<void()> onSignal) {
    if (::pipe(pipeEnds) != 0) throw std::runtime_error("cannot make the studio's signal pipe");
    rt::installTempFileCleanup();   // first, so that ours replace its SIGINT and SIGTERM
    struct sigaction action {};
    action.sa_handler = signalled;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    thread_ = std::thread([onSignal = std::move(onSignal)] {
        char byte = 0;
        while (::read(pipeEnds[0], &byte, 1) < 0) {
        }
        if (byte != 0) onSignal();   // 0: the destructor's wake-up
    });
}

ShutdownSignal::~ShutdownSignal() {
    const char zero = 0;
    [[maybe_unused]] auto n = ::write(pipeEnds[1], &zero, 1);
    thread_.join();
    ::close(pipeEnds[0]);
    ::close(pipeEnds[1]);
}

}  // namespace g2d::studio
