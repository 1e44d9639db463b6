#pragma once
// The studio's page: an HTML shell whose script (/studio.js) is served from
// the binary too, and the Content-Security-Policy that keeps it to its own
// server (no network; an SVG's scripts and handlers never run).
#include <string>

#include "studio/studio_script.hpp"

namespace g2d::studio {

const std::string& studioPage();
const char* studioPagePolicy();
inline const std::string& studioScript() { return rt::studioScript(); }

}  // namespace g2d::studio
