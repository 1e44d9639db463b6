// libFuzzer target 2: the front end on structure-aware mutations of real
// grammars (the examples and tests/bad): tokens are deleted, duplicated,
// swapped and replaced by g2d keywords, operators and names, and lines of
// two grammars are spliced, so that inputs get deep into semantic analysis.
#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    g2d::fuzz::checkFrontEnd(data, size);
    return 0;
}

// The token-level mutation hooks: token_mutator_hooks.cpp.
