#include "g2d/source_excerpt.hpp"
#include "g2d/utf8.hpp"

#include <algorithm>
#include <vector>

namespace g2d::rt {

namespace {

// The line as printable code points, one string each.
std::vector<std::string> printableCodePoints(const std::string& raw) {
    static const std::string replacement = "\xEF\xBF\xBD";
    std::vector<std::string> out;
    for (std::size_t i = 0; i < raw.size();) {
        const auto c = static_cast<unsigned char>(raw[i]);
        if (c == '\t') { out.emplace_back(" "); ++i; continue; }
        if (c < 0x20 || c == 0x7f) { out.push_back(replacement); ++i; continue; }
        const std::size_t n = utf8SequenceLength(raw, i);
        if (n == 0) { out.push_back(replacement); ++i; continue; }
        out.push_back(raw.substr(i, n));
        i += n;
    }
    return out;
}

}  // namespace

Excerpt excerptLine(const std::string& rawLine, std::uint32_t col, std::uint32_t endCol) {
    const std::vector<std::string> points = printableCodePoints(rawLine);
    const std::size_t at = col > 0 ? col - 1 : 0;                         // 0-based caret column
    std::size_t width = endCol > col ? endCol - col : 1;
    std::size_t begin = 0, end = points.size();
    if (points.size() > kExcerptWidth) {
        // Keep some context before the caret, and as much after as fits.
        begin = at > kExcerptWidth / 3 ? at - kExcerptWidth / 3 : 0;
        begin = std::min(begin, points.size() - std::min(points.size(), kExcerptWidth));
        end = std::min(points.size(), begin + kExcerptWidth);
    }
    Excerpt ex;
    if (begin > 0) ex.line += "…";
    for (std::size_t i = begin; i < end; ++i) ex.line += points[i];
    if (end < points.size()) ex.line += "…";
    ex.pad = (begin > 0 ? 1 : 0) + (std::min(at, end) - std::min(at, begin));
    if (at + width > end && end < points.size()) width = std::max<std::size_t>(1, end - std::min(at, end));
    ex.width = width;
    return ex;
}

}  // namespace g2d::rt
