// libFuzzer target 2: the front end on structure-aware mutations of real
// grammars (the examples and tests/bad): tokens are deleted, duplicated,
// swapped and replaced by g2d keywords, operators and names, and lines of
// two grammars are spliced, so that inputs get deep into semantic analysis.
#include "fuzz_checks.hpp"
#include "token_mutator.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    g2d::fuzz::checkFrontEnd(data, size);
    return 0;
}

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t maxSize,
                                               unsigned int seed) {
    return g2d::fuzz::mutateTokens(data, size, maxSize, seed);
}

extern "C" std::size_t LLVMFuzzerCustomCrossOver(const std::uint8_t* a, std::size_t sizeA, const std::uint8_t* b,
                                                 std::size_t sizeB, std::uint8_t* out, std::size_t maxOut,
                                                 unsigned int seed) {
    return g2d::fuzz::crossOverLines(a, sizeA, b, sizeB, out, maxOut, seed);
}
