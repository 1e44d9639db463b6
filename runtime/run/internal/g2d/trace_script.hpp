#pragma once
// The script of a 2D grammar's --trace page: the player (web/view/src/trace2d.js),
// bundled by npm and embedded by CMake at build time (cmake/embed_text.cmake),
// so the page works offline and alone. A 3D grammar's page uses viewScript().
#include <string>

namespace g2d::rt {

const std::string& traceScript();

}  // namespace g2d::rt
