#include "g2d/png_writer.hpp"

#include <algorithm>
#include <cairo.h>
#include <cmath>
#include <gio/gio.h>
#include <librsvg/rsvg.h>
#include <stdexcept>

namespace g2d::rt {

namespace {

// cairo's image surfaces are at most this many pixels on a side.
constexpr double kMaxSide = 32767;

std::string takeError(GError* error, const std::string& fallback) {
    if (!error) return fallback;
    std::string message = error->message ? error->message : fallback;
    g_error_free(error);
    return message;
}

cairo_status_t appendBytes(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

// Owners of the C objects, released on every path.
struct Handle {
    RsvgHandle* p = nullptr;
    ~Handle() {
        if (p) g_object_unref(p);
    }
};
struct Surface {
    cairo_surface_t* p = nullptr;
    ~Surface() {
        if (p) cairo_surface_destroy(p);
    }
};
struct Context {
    cairo_t* p = nullptr;
    ~Context() {
        if (p) cairo_destroy(p);
    }
};

}  // namespace

bool isPngPath(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".png";
}

std::string renderPng(const std::string& svg, const PngOptions& options) {
    GError* error = nullptr;
    GInputStream* stream = g_memory_input_stream_new_from_data(svg.data(), static_cast<gssize>(svg.size()), nullptr);
    GFile* base = options.baseFile.empty() ? nullptr : g_file_new_for_path(options.baseFile.c_str());
    Handle handle{rsvg_handle_new_from_stream_sync(stream, base, RSVG_HANDLE_FLAGS_NONE, nullptr, &error)};
    g_object_unref(stream);
    if (base) g_object_unref(base);
    if (!handle.p) throw std::runtime_error("cannot read the SVG to render: " + takeError(error, "unknown error"));

    const double dpi = options.dpi.value_or(96.0);
    rsvg_handle_set_dpi(handle.p, dpi);
    gdouble w = 0, h = 0;
    if (!rsvg_handle_get_intrinsic_size_in_pixels(handle.p, &w, &h) || !(w > 0) || !(h > 0))
        throw std::runtime_error("the SVG has no size to render");
    if (options.width) {   // w, h at `dpi` (96): scaled to the width asked for
        h = h * *options.width / w;
        w = *options.width;
    }
    const double pw = std::max(1.0, std::round(w)), ph = std::max(1.0, std::round(h));
    if (pw > kMaxSide || ph > kMaxSide)
        throw std::runtime_error("the image would be " + std::to_string(static_cast<long long>(pw)) + " x " +
                                 std::to_string(static_cast<long long>(ph)) +
                                 " pixels, more than the 32767 a side a PNG can be rendered at here (lower --dpi or --width)");

    Surface surface{cairo_image_surface_create(CAIRO_FORMAT_ARGB32, static_cast<int>(pw), static_cast<int>(ph))};
    if (cairo_surface_status(surface.p) != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(std::string("cannot make the image: ") + cairo_status_to_string(cairo_surface_status(surface.p)));
    Context cr{cairo_create(surface.p)};
    const RsvgRectangle viewport{0, 0, pw, ph};
    if (!rsvg_handle_render_document(handle.p, cr.p, &viewport, &error))
        throw std::runtime_error("cannot render the SVG: " + takeError(error, "unknown error"));
    if (cairo_status(cr.p) != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(std::string("cannot render the SVG: ") + cairo_status_to_string(cairo_status(cr.p)));
    cairo_surface_flush(surface.p);
    std::string png;
    const cairo_status_t status = cairo_surface_write_to_png_stream(surface.p, appendBytes, &png);
    if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error(std::string("cannot encode the PNG: ") + cairo_status_to_string(status));
    return png;
}

}  // namespace g2d::rt
