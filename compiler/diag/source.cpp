#include "diag/source.hpp"

namespace g2d {

FileId SourceManager::add(std::string path, std::string text) {
    SourceFile f;
    f.path = std::move(path);
    f.text = std::move(text);
    f.lineStarts.push_back(0);
    for (std::size_t i = 0; i < f.text.size(); ++i)
        if (f.text[i] == '\n') f.lineStarts.push_back(i + 1);
    files_.push_back(std::move(f));
    return static_cast<FileId>(files_.size() - 1);
}

std::string SourceManager::lineText(FileId id, std::uint32_t line) const {
    if (id >= files_.size()) return {};
    const auto& f = files_[id];
    if (line == 0 || line > f.lineStarts.size()) return {};
    std::size_t begin = f.lineStarts[line - 1];
    std::size_t end = f.text.find('\n', begin);
    if (end == std::string::npos) end = f.text.size();
    if (end > begin && f.text[end - 1] == '\r') --end;
    return f.text.substr(begin, end - begin);
}

}  // namespace g2d
