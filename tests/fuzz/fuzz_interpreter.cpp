// libFuzzer target 3: the interpreter on grammars that pass the front end,
// under step, element and time budgets, with incremental matching verified
// against a full search after every step. Inputs are mutated as tokens (see
// token_mutator.hpp), so that most of them stay valid grammars.
#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    g2d::fuzz::checkInterpreter(data, size);
    return 0;
}

// The token-level mutation hooks: token_mutator_hooks.cpp.
