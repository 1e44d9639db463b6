#pragma once
// What the page gets of a run: its picture (2D: the SVG; 3D: the --view
// page's model), its parameters, and on request its trace; a file to
// download, made as `g2d run` makes it; or a sheet of small pictures, one
// per seed.
#include <cstdint>
#include <functional>
#include <string>

#include "studio/api_reply.hpp"
#include "studio/run_request.hpp"

namespace g2d::studio {

class ImageShelf;

// 200 {"status": "ok", "space", "svg" (2D) | "model" (3D), "trace"?,
// "params", "steps", "stopped", "elements": {nodes, edges, faces}, "ms",
// "diagnostics", "warning"?}; 422 {"status": "invalid", "diagnostics"} for
// a grammar with errors; 422 {"status": "error", "message", "location"?,
// "stopped"?, "params"?} for a run that failed; 409 {"status": "cancelled"}.
// `cancelled` is asked after every step. With `images`, the SVG links the
// image files it draws by their addresses on that shelf.
ApiReply deriveText(const std::string& path, const RunInput& input, const std::function<bool()>& cancelled,
                    ImageShelf* images = nullptr);

// The bytes `g2d run` would write for `format` (the SVG, the PNG, …), or a
// 422 JSON answer saying why there are none.
ApiReply exportText(const std::string& path, const RunInput& input, ExportFormat format,
                    const std::function<bool()>& cancelled);

// {"status": "ok", "sheet": [{"seed", "png" (a data: URL) | "message", "steps", "elements", "stopped"}]}
// for seeds first, first+1, …: each a PNG `width` pixels wide. One failed
// seed says why in its own cell.
ApiReply seedSheet(const std::string& path, const RunInput& input, std::uint64_t first, int count, int width,
                   const std::function<bool()>& cancelled);

}  // namespace g2d::studio
