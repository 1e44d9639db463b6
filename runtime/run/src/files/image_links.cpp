#include "g2d/image_links.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "g2d/atomic_file.hpp"

namespace g2d::rt {
namespace fs = std::filesystem;
bool isUrlHref(const std::string& href) {
    if (href.empty() || href[0] == '#') return true;
    const auto colon = href.find(':');
    const auto slash = href.find('/');
    return colon != std::string::npos && colon > 1 && (slash == std::string::npos || colon < slash);
}

std::string imageMediaType(const std::string& file) {
    std::string ext = fs::path(file).extension().string();
    for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".png") return "image/png";
    if (ext == ".jpg" || ext == ".jpeg") return "image/jpeg";
    if (ext == ".gif") return "image/gif";
    if (ext == ".svg") return "image/svg+xml";
    if (ext == ".webp") return "image/webp";
    return "application/octet-stream";
}

std::string base64(const std::string& bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                           static_cast<unsigned char>(bytes[i + 2]);
        out += kDigits[v >> 18];
        out += kDigits[(v >> 12) & 63];
        out += kDigits[(v >> 6) & 63];
        out += kDigits[v & 63];
    }
    if (i < bytes.size()) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        out += kDigits[v >> 18];
        out += kDigits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

ImageLinks::ImageLinks(const std::string& grammarFile, const std::string& outputFile, bool embed)
    : grammarDir_(fs::absolute(grammarFile).parent_path().lexically_normal().string()),
      outputDir_(fs::absolute(outputFile).parent_path().lexically_normal().string()),
      embed_(embed) {}

std::string ImageLinks::href(const std::string& grammarHref) {
    if (isUrlHref(grammarHref)) return grammarHref;
    if (auto it = done_.find(grammarHref); it != done_.end()) return it->second;
    const fs::path file = (fs::path(grammarDir_) / grammarHref).lexically_normal();
    std::string out;
    if (embed_) {
        std::ifstream in(file, std::ios::binary);
        if (!in) throw OutputError("cannot embed the image `" + grammarHref + "`: " + file.string() + " cannot be read");
        std::stringstream bytes;
        bytes << in.rdbuf();
        out = "data:" + imageMediaType(file.string()) + ";base64," + base64(bytes.str());
    } else {
        out = file.lexically_relative(outputDir_).generic_string();
        if (out.empty()) out = file.generic_string();
    }
    return done_.emplace(grammarHref, std::move(out)).first->second;
}

}  // namespace g2d::rt
