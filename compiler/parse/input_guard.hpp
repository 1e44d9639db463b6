#pragma once
// Checks made before parsing, so that no input can crash or exhaust the parser:
// encoding (valid UTF-8, no binary data) and nesting depth.
#include <antlr4-runtime.h>

#include "diag/diagnostic.hpp"
#include "parse/parser.hpp"

namespace g2d {

bool checkEncoding(const SourceFile& src, FileId file, Diagnostics& diags);
bool checkNesting(const std::vector<antlr4::Token*>& tokens, FileId file, const ParseLimits& limits,
                  Diagnostics& diags);

}  // namespace g2d
