#pragma once
// The studio's page and script, served from the binary, and the
// Content-Security-Policy that keeps the page to its own server (no network;
// an SVG's scripts and handlers never run).
#include <string>

#include "studio/studio_assets.hpp"

namespace g2d::studio {

inline const std::string& studioPage() { return rt::studioPageHtml(); }
inline const std::string& studioScript() { return rt::studioScript(); }
const char* studioPagePolicy();

}  // namespace g2d::studio
