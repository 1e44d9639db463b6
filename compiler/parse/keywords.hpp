#pragma once
// The language's keywords, read from the lexer ANTLR generates from
// grammar/G2d.g4 (its identifier-like literals), so that editor completion
// and the importer's reserved names never miss a new keyword.
#include <string>
#include <vector>

namespace g2d::parse {

const std::vector<std::string>& keywords();

}  // namespace g2d::parse
