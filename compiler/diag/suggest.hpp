#pragma once
// "Did you mean …?": the closest of some candidates to a misspelt name, for
// the parser's and the checker's messages alike.
#include <string>
#include <vector>

namespace g2d {

// "; did you mean `x`?" when some candidate is close to `name` (one edit per
// three characters); "" otherwise.
std::string suggest(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace g2d
