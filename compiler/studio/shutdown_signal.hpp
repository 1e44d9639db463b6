#pragma once
// SIGINT and SIGTERM end the studio cleanly: the handler only writes a byte
// to a pipe (all a handler may safely do), and a thread reading the pipe
// calls `onSignal` (which stops the server). Installed after the atomic
// file writer's own handlers, which would otherwise end the process.
#include <functional>
#include <thread>

namespace g2d::studio {

class ShutdownSignal {
public:
    explicit ShutdownSignal(std::function<void()> onSignal);
    ~ShutdownSignal();   // wakes and joins the thread (without calling onSignal)
    ShutdownSignal(const ShutdownSignal&) = delete;
    ShutdownSignal& operator=(const ShutdownSignal&) = delete;

private:
    std::thread thread_;
};

}  // namespace g2d::studio
