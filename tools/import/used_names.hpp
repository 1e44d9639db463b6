#pragma once
// Which declared names (a grammar's consts, a rule's lets) the written code
// uses, so that the import declares only those: g2d warns of a name nothing
// reads, and `check --werror` must pass on an import.
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace g2d::import {

// The names of `declared` (name, its expression) that `code` reads, directly
// or through the expression of another used one. Comments (`//` to the end
// of a line, outside a string) are not code.
std::set<std::string> usedNames(const std::string& code, const std::vector<std::pair<std::string, std::string>>& declared);

}  // namespace g2d::import
