#pragma once
// UTF-8 validity, for every reader of text g2d writes back out (grammars,
// the original tool's YAML): one definition of a valid sequence.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace g2d::rt {

// Length of the valid UTF-8 sequence at `i` (1-4), or 0 if it is not one
// (a stray continuation byte, a truncated, overlong or surrogate sequence,
// a code point past U+10FFFF). With `codePoint`, the code point it encodes.
std::size_t utf8SequenceLength(std::string_view text, std::size_t i, std::uint32_t* codePoint = nullptr);

// Code points in UTF-8 text: the bytes that are not continuation bytes (so a
// column counted on any text, valid or not, is the same everywhere).
std::size_t codePointCount(std::string_view text);

// The offset of the first byte that starts no valid sequence, or npos.
std::size_t firstInvalidUtf8(std::string_view text);

}  // namespace g2d::rt
