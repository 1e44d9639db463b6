#pragma once
// The one file the studio edits: read with a version, written atomically
// (the run library's AtomicFile) only when the client saw the latest
// version. Nothing else on disk is ever written, and no request names a
// path: the file is the one the studio was started with.
#include <mutex>
#include <optional>
#include <string>

namespace g2d::studio {

struct FileState {
    bool exists = false;
    std::string text;
    std::string version;   // of the text (a hash): changes whenever the bytes do; "none" for no file
};

struct SaveResult {
    enum class Outcome { Saved, Stale, NoFile, Failed };
    Outcome outcome = Outcome::Failed;
    std::string version;   // the file's version after the save, or the one on disk that refused it
    std::string error;     // why it was not saved
};

class EditedFile {
public:
    // `path` as the user gave it ("" when the studio edits no file).
    explicit EditedFile(std::string path);

    const std::string& path() const { return path_; }
    FileState read() const;
    // Writes `text` if the file on disk is still at `expectedVersion`.
    SaveResult save(const std::string& text, const std::string& expectedVersion);

private:
    std::string path_;
    mutable std::mutex mutex_;   // a save's check and write happen together
};

// The version of a text: 16 hex digits of its FNV-1a hash.
std::string versionOf(const std::string& text);

}  // namespace g2d::studio
