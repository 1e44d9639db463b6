#pragma once
// `g2d check FILE…`
#include <string>
#include <vector>

namespace g2d {

enum class DiagnosticsFormat { Text, Json };

// Prints diagnostics to stderr (text) or stdout (json). Returns the exit
// code: 0 valid, 1 errors (or warnings with `werror`).
int runCheck(const std::vector<std::string>& files, DiagnosticsFormat format, bool werror);

}  // namespace g2d
