#pragma once
// `g2d import`: the original tool's YAML grammar (model_gen) as g2d source.

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

// fileName is named in the output's header comment.
ImportedGrammar importModelGen(const MgGrammar& grammar, const std::string& fileName);

}  // namespace g2d::import
