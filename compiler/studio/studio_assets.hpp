#pragma once
// The studio page (web/studio/page.html) and its script (the bundle of
// web/studio/src), embedded by CMake at build time (cmake/embed_text.cmake):
// the page needs nothing from disk.
#include <string>

namespace g2d::rt {

const std::string& studioPageHtml();
const std::string& studioScript();

}  // namespace g2d::rt
