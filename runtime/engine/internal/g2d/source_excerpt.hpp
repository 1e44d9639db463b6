#pragma once
// The source line shown under an error, and where its caret goes. Shared by
// the front end's diagnostics and run-time errors, so both look the same.
//
// Columns count code points (as spans do). Tabs become one space and control
// bytes or invalid UTF-8 become U+FFFD, one column each, so the caret lines
// up in any terminal. A line longer than kExcerptWidth code points is cut to
// a window around the column, marked with … at each cut end.
#include <cstddef>
#include <cstdint>
#include <string>

namespace g2d::rt {

inline constexpr std::size_t kExcerptWidth = 160;

struct Excerpt {
    std::string line;        // what to print of the source line
    std::size_t pad = 0;     // columns before the caret
    std::size_t width = 1;   // columns the caret and its ~ cover
};

// `endCol` on the same line, or 0 for a single column.
Excerpt excerptLine(const std::string& rawLine, std::uint32_t col, std::uint32_t endCol);

}  // namespace g2d::rt
