#pragma once
// Where an SVG's images are found: a grammar names an image relative to its
// own folder; the SVG needs it relative to where the SVG is written, or, with
// --embed-images, as a data: URI so that the file stands alone.

#include <map>
#include <string>

namespace g2d::rt {

class ImageLinks {
public:
    // grammarFile: the .g2d file; outputFile: the SVG (or page) being written.
    ImageLinks(const std::string& grammarFile, const std::string& outputFile, bool embed);

    // The href to write for the grammar's `href`. URLs (data:, http:, …) and
    // fragments stay as they are. Throws OutputError when an image to embed
    // cannot be read.
    std::string href(const std::string& grammarHref);

private:
    std::string grammarDir_, outputDir_;
    bool embed_;
    std::map<std::string, std::string> done_;   // an image drawn many times is read once
};

// Whether an image's href is a URL (data:, http:, …) or a fragment, not a file.
bool isUrlHref(const std::string& href);

// The media type of an image file by its extension (image/png, …), or
// application/octet-stream for another file.
std::string imageMediaType(const std::string& file);

// RFC 4648 base64 of bytes.
std::string base64(const std::string& bytes);

}  // namespace g2d::rt
