#include "studio/image_shelf.hpp"

#include <filesystem>
#include <system_error>

#include "g2d/image_links.hpp"

namespace g2d::studio {
namespace fs = std::filesystem;

std::string ImageShelf::hrefFor(const std::string& grammarFile, const std::string& grammarHref) {
    if (rt::isUrlHref(grammarHref)) return grammarHref;
    const fs::path file = (fs::absolute(grammarFile).parent_path() / grammarHref).lexically_normal();
    const std::string mediaType = rt::imageMediaType(file.string());
    std::error_code error;
    if (mediaType.rfind("image/", 0) != 0 || !fs::is_regular_file(file, error)) return grammarHref;
    std::lock_guard lock(mutex_);
    auto it = indexOf_.find(file.string());
    if (it == indexOf_.end()) {
        if (images_.size() >= kMaxImages) return grammarHref;
        it = indexOf_.emplace(file.string(), images_.size()).first;
        images_.push_back({file.string(), mediaType});
    }
    return "/api/image/" + std::to_string(it->second);
}

std::optional<ImageShelf::Image> ImageShelf::image(std::size_t index) const {
    std::lock_guard lock(mutex_);
    if (index >= images_.size()) return std::nullopt;
    return images_[index];
}

}  // namespace g2d::studio
