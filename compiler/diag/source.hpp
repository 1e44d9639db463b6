#pragma once
// Source files as loaded by the compiler, and positions inside them.
#include <cstdint>
#include <string>
#include <vector>

namespace g2d {

using FileId = std::uint32_t;
inline constexpr FileId kNoFile = 0xffffffffu;

// A half-open region of one source file; lines and columns are 1-based,
// columns count characters (code points), as editors show them.
struct Span {
    FileId file = kNoFile;
    std::uint32_t line = 0, col = 0;
    std::uint32_t endLine = 0, endCol = 0;
    bool valid() const { return file != kNoFile && line > 0; }
};

struct SourceFile {
    std::string path;     // as given or resolved (what diagnostics print)
    std::string text;
    std::vector<std::size_t> lineStarts;  // byte offset of each line
};

class SourceManager {
public:
    FileId add(std::string path, std::string text);
    const SourceFile& file(FileId id) const { return files_.at(id); }
    std::size_t size() const { return files_.size(); }
    // The text of one line without its line terminator ("" if out of range).
    std::string lineText(FileId id, std::uint32_t line) const;

private:
    std::vector<SourceFile> files_;
};

}  // namespace g2d
