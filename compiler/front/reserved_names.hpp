#pragma once
// The names a grammar's own names must avoid, from the tables the parser and
// the checker use: keywords (the lexer's), types, built-in functions and
// constants, and the facts every element has. The importer renames around
// them; editors list the keywords.
#include <set>
#include <string>
#include <vector>

namespace g2d::front {

const std::vector<std::string>& keywords();
const std::set<std::string>& keywordNames();   // the same, as a set
const std::set<std::string>& reservedNames();
// What an attribute cannot be named (keywords, and the facts the checker
// refuses as attributes): the importer leaves such keys of the tool out.
const std::set<std::string>& attributeNamesRefused();

}  // namespace g2d::front
