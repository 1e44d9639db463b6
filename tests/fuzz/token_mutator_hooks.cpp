// libFuzzer's hooks for structure-aware mutation (token_mutator.hpp), linked
// into the targets that mutate g2d source as tokens.
#include "token_mutator.hpp"

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t maxSize,
                                               unsigned int seed) {
    return g2d::fuzz::mutateTokens(data, size, maxSize, seed);
}

extern "C" std::size_t LLVMFuzzerCustomCrossOver(const std::uint8_t* a, std::size_t sizeA, const std::uint8_t* b,
                                                 std::size_t sizeB, std::uint8_t* out, std::size_t maxOut,
                                                 unsigned int seed) {
    return g2d::fuzz::crossOverLines(a, sizeA, b, sizeB, out, maxOut, seed);
}
