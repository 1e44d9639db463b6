#pragma once
// `g2d studio [FILE] [--port N]`: a local server for editing a grammar and
// watching its picture (docs/studio.md). It listens on 127.0.0.1 only,
// prints its URL as the first line of standard output, and serves until
// SIGINT or SIGTERM.

#include <string>

namespace g2d::studio {

struct StudioOptions {
    std::string file;   // "" : no file (nothing can be saved)
    int port = 0;       // 0: any free port
};

// Returns the exit code: 0 after a signal, 1 when the port cannot be had or
// FILE is not a file (a folder).
int runStudio(const StudioOptions& options);

}  // namespace g2d::studio
