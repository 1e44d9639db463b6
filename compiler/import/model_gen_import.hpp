#pragma once
// `g2d import`: the original tool's YAML grammar (model_gen) as g2d source.

#include <set>
#include <string>
#include <vector>

#include "import/model_gen_grammar.hpp"

namespace g2d::import {

struct ImportWarning {
    int line = 0;             // 1-based line of the YAML file
    std::string message;
};

struct ImportedGrammar {
    std::string source;       // the .g2d text
    std::vector<ImportWarning> warnings;
};

// fileName is named in the output's header comment. `reserved`: the names
// g2d's own (keywords, types, built-ins, facts: front::reservedNames), which
// the grammar's names avoid; the importer adds its kinds, Vertex and Edge.
ImportedGrammar importModelGen(const MgGrammar& grammar, const std::string& fileName, const std::set<std::string>& reserved);

}  // namespace g2d::import
