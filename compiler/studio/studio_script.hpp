#pragma once
// The studio page's script (web/studio/studio.js), embedded by CMake at
// build time (cmake/embed_text.cmake): the page needs nothing from disk.
#include <string>

namespace g2d::rt {

const std::string& studioScript();

}  // namespace g2d::rt
