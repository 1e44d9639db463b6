#pragma once
// The compiler's passes (AST building, checking, folding, the interpreter's
// evaluator) recurse over expressions, which may be 4000 operators deep
// (ParseLimits): too deep for an 8 MiB main-thread stack in some passes, and
// for any stack under AddressSanitizer. So the work runs on a thread with a
// large stack (address space only: untouched pages cost nothing).
#include <cstddef>
#include <functional>

namespace g2d {

inline constexpr std::size_t kBigStackBytes = std::size_t{1} << 30;   // 1 GiB

// Runs `work` on a thread with a `bytes` stack and returns its result; runs it
// here if no such thread can be made.
int runWithBigStack(const std::function<int()>& work, std::size_t bytes = kBigStackBytes);

}  // namespace g2d
