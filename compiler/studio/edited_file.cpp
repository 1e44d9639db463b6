#include "studio/edited_file.hpp"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "g2d/atomic_file.hpp"

namespace g2d::studio {

std::string versionOf(const std::string& text) {
    std::uint64_t h = 1469598103934665603ULL;
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ULL;
    char out[17];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
    return out;
}

EditedFile::EditedFile(std::string path) : path_(std::move(path)) {}

FileState EditedFile::read() const {
    FileState state;
    state.version = "none";
    if (path_.empty()) return state;
    std::ifstream in(path_, std::ios::binary);
    if (!in) return state;
    std::ostringstream text;
    text << in.rdbuf();
    state.exists = true;
    state.text = text.str();
    state.version = versionOf(state.text);
    return state;
}

SaveResult EditedFile::save(const std::string& text, const std::string& expectedVersion) {
    std::lock_guard<std::mutex> lock(mutex_);
    SaveResult result;
    if (path_.empty()) {
        result.outcome = SaveResult::Outcome::NoFile;
        result.error = "the studio was started without a file: start it as `g2d studio FILE` to save";
        return result;
    }
    const FileState now = read();
    if (now.version != expectedVersion) {
        result.outcome = SaveResult::Outcome::Stale;
        result.version = now.version;
        result.error = "`" + path_ + "` changed on disk since version " + expectedVersion + " (now " + now.version +
                       "): reload it, or save again with the new version to overwrite";
        return result;
    }
    try {
        rt::AtomicFile file(path_);
        file.commit(text);
    } catch (const std::exception& e) {
        result.version = now.version;
        result.error = e.what();
        return result;
    }
    result.outcome = SaveResult::Outcome::Saved;
    result.version = versionOf(text);
    return result;
}

}  // namespace g2d::studio
