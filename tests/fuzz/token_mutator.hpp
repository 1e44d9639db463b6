#pragma once
// Structure-aware mutation for libFuzzer: g2d source is cut into tokens
// (names, numbers, strings, comments, white space, punctuation) and changed a
// token at a time, or two sources are spliced line-wise, so that mutated
// grammars mostly still parse and reach semantic analysis and the derivation.
#include <cstddef>
#include <cstdint>

namespace g2d::fuzz {

// Mutates data[0, size) in place; returns the new size (at most maxSize).
std::size_t mutateTokens(std::uint8_t* data, std::size_t size, std::size_t maxSize, unsigned int seed);

// Lines of `a` up to a random point, then lines of `b` from a random point.
std::size_t crossOverLines(const std::uint8_t* a, std::size_t sizeA, const std::uint8_t* b, std::size_t sizeB,
                           std::uint8_t* out, std::size_t maxOut, unsigned int seed);

}  // namespace g2d::fuzz
