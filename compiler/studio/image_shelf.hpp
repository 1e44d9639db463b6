#pragma once
// The image files a grammar's drawing links (a style's `href`, relative to
// the grammar's folder), for the page's SVG. Each image file named gets an
// address, /api/image/N; the studio serves those files and no others, so an
// address cannot name a file the grammar did not.
#include <cstddef>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace g2d::studio {

class ImageShelf {
public:
    struct Image {
        std::string path, mediaType;
    };

    // The href for the page's SVG in place of `grammarHref`, written in the
    // grammar `grammarFile`: a URL or fragment stays; an existing png, jpeg,
    // gif, svg or webp file gets its address; anything else stays as
    // written, and shows broken as in the SVG `g2d run` writes.
    std::string hrefFor(const std::string& grammarFile, const std::string& grammarHref);

    // The image at /api/image/`index`, if one was given that address.
    std::optional<Image> image(std::size_t index) const;

    // More distinct files than this keep their hrefs (the shelf does not grow without end).
    static constexpr std::size_t kMaxImages = 1024;

private:
    mutable std::mutex mutex_;
    std::vector<Image> images_;
    std::map<std::string, std::size_t> indexOf_;   // by absolute path
};

}  // namespace g2d::studio
