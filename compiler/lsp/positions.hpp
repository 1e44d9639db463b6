#pragma once
// Positions: the compiler counts lines from 1 and columns in code points
// from 1; LSP counts lines from 0 and characters in UTF-16 code units from 0.
#include <cstdint>
#include <string>

namespace g2d::lsp {

// UTF-16 offset of code-point column `col` (1-based) in `line`.
std::uint32_t utf16Offset(const std::string& line, std::uint32_t col);
// Code-point column (1-based) of UTF-16 offset `character` in `line`.
std::uint32_t codePointColumn(const std::string& line, std::uint32_t character);
// The byte offset in `text` of LSP position (line, UTF-16 character), both
// from 0: past a line's end is its end (before the line break), past the
// last line is the text's end, and inside a character is its start.
std::size_t byteOffset(const std::string& text, std::uint32_t line, std::uint32_t character);
// The identifier ([A-Za-z_][A-Za-z0-9_]*) covering code-point column `col`
// (or ending just before it), with its first column; empty if none.
std::string identifierAt(const std::string& line, std::uint32_t col, std::uint32_t* start = nullptr);

std::string pathToUri(const std::string& path);
std::string uriToPath(const std::string& uri);

}  // namespace g2d::lsp
