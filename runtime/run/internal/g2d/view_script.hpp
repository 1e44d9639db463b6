#pragma once
// The script of the --view page: three.js, its orbit controls and the page's
// own code (web/view), bundled by npm and embedded by CMake at build time
// (cmake/embed_text.cmake), so the page works offline and alone.
#include <string>

namespace g2d::rt {

const std::string& viewScript();

}  // namespace g2d::rt
