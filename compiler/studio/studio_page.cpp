#include "studio/studio_page.hpp"

namespace g2d::studio {

// blob: images are the large-drawing preview and the downloads; data: images the seeds sheet.
const char* studioPagePolicy() {
    return "default-src 'none'; script-src 'self'; connect-src 'self'; style-src 'unsafe-inline'; img-src 'self' data: blob:; "
           "base-uri 'none'; form-action 'none'; frame-ancestors 'self'";
}

}  // namespace g2d::studio
