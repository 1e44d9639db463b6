// libFuzzer target 3: the interpreter on grammars that pass the front end,
// under step, element and time budgets, with incremental matching verified
// against a full search after every step. Inputs are mutated as tokens (see
// token_mutator.hpp), so that most of them stay valid grammars.
#include <cstdlib>

#include "fuzz_checks.hpp"
#include "token_mutator.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    setenv("G2D_VERIFY_MATCHES", "1", 1);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    g2d::fuzz::checkInterpreter(data, size);
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
