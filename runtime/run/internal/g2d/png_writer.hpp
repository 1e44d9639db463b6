#pragma once
// PNG output (`-o x.png`): the SVG that g2d writes, rendered by librsvg onto
// a cairo image surface. Deterministic: the same SVG gives the same bytes.
#include <optional>
#include <string>

namespace g2d::rt {

// Whether `path` names a PNG output: it ends in `.png`, in any case.
bool isPngPath(const std::string& path);

struct PngOptions {
    std::optional<double> dpi;        // pixels per inch for the SVG's size in cm (default 96)
    std::optional<int> width;         // or: this many pixels wide, the height by the aspect ratio
    std::string baseFile;             // relative hrefs (images) resolve against this file's folder ("" = none)
};

// Renders `svg` to the bytes of a PNG file. Throws std::runtime_error with
// the reason (librsvg's or cairo's) when it cannot.
std::string renderPng(const std::string& svg, const PngOptions& options);

}  // namespace g2d::rt
