#include "studio/studio.hpp"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>
#include <httplib.h>

#include "studio/edited_file.hpp"
#include "studio/file_watch.hpp"
#include "studio/grammar_jobs.hpp"
#include "studio/shutdown_signal.hpp"
#include "studio/studio_routes.hpp"

namespace g2d::studio {

int runStudio(const StudioOptions& options) {
    std::error_code error;
    if (!options.file.empty() && std::filesystem::exists(options.file, error) &&
        !std::filesystem::is_regular_file(options.file, error)) {
        std::fprintf(stderr, "g2d studio: error: `%s` is not a file\n", options.file.c_str());
        return 1;
    }
    EditedFile file(options.file);
    FileWatch watch(file);
    GrammarJobs jobs(options.file);
    httplib::Server server;
    // An answer goes out at once: with Nagle's algorithm, its last small write waited for the
    // browser's delayed ACK, and every picture came 200 ms late.
    server.set_tcp_nodelay(true);
    int port = 0;
    addStudioRoutes(server, StudioParts{file, watch, jobs, port});

    const char* host = "127.0.0.1";   // loopback only: never reachable from another machine
    port = options.port == 0 ? server.bind_to_any_port(host) : (server.bind_to_port(host, options.port) ? options.port : -1);
    if (port <= 0) {
        std::fprintf(stderr, "g2d studio: error: cannot listen on %s:%d (in use?)\n", host, options.port);
        return 1;
    }
    std::atomic<bool> signalled{false}, listened{false};
    {
        // Ready before the URL is printed: a client may signal as soon as it reads it.
        ShutdownSignal shutdown([&] {
            signalled = true;
            watch.stop();        // ends the event streams, which hold server threads
            jobs.cancelRuns();   // and the run in flight
            // stop() does nothing before listening has begun.
            while (!server.is_running() && !listened) std::this_thread::sleep_for(std::chrono::milliseconds(1));
            server.stop();
        });
        std::printf("http://%s:%d/\n", host, port);
        std::fflush(stdout);
        server.listen_after_bind();
        listened = true;
    }
    std::fprintf(stderr, "g2d studio: %s\n", signalled ? "stopped" : "the server ended");
    return signalled ? 0 : 1;
}

}  // namespace g2d::studio
