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

// The names g2d keeps for itself, from the tables its parser and checker use.
struct G2dNames {
    // Keywords, types, built-ins, facts (front::reservedNames): the grammar's
    // names avoid them; the importer adds its kinds, Vertex and Edge.
    const std::set<std::string>& reserved;
    // What an attribute cannot be named (front::attributeNamesRefused): keys
    // of the tool's that are such names (or no names) are left out.
    const std::set<std::string>& notAttributes;
    // What cannot follow `style.` (the keywords, front::keywordNames); such
    // `.svg_` properties are left out.
    const std::set<std::string>& notStyles;
};

// fileName is named in the output's header comment.
ImportedGrammar importModelGen(const MgGrammar& grammar, const std::string& fileName, const G2dNames& names);

}  // namespace g2d::import
