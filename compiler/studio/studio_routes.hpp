#pragma once
// The studio's HTTP surface on a cpp-httplib server: the guard before
// routing (request_guard.hpp), the page and its script (from the binary),
// and the JSON API:
//   GET  /api/file     the edited file: {"path", "exists", "text", "version"}
//   PUT  /api/file     {"text", "version"} → saved atomically, or 409 when
//                      the file changed on disk since that version
//   GET  /api/imports  the files the grammar imports: {"files": [{"name", "text"}]}
//   POST /api/check    {"text"} → the diagnostics of `g2d check`
//   POST /api/run      {"text", "params", "seed", "steps", "timeout"} → the picture
//   GET  /api/image/N  an image file the page's SVG links (image_shelf.hpp)
//   GET  /api/events   Server-Sent Events: `file` when the file changes on disk
namespace httplib {
class Server;
}

namespace g2d::studio {

class EditedFile;
class FileWatch;
class GrammarJobs;

// The largest request body accepted (larger: 413); grammars are at most 8 MiB.
inline constexpr unsigned long kMaxRequestBytes = 16ul << 20;

struct StudioParts {
    EditedFile& file;
    FileWatch& watch;
    GrammarJobs& jobs;
    const int& port;   // known once bound
};

void addStudioRoutes(httplib::Server& server, StudioParts parts);

}  // namespace g2d::studio
