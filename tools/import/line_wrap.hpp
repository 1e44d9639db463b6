#pragma once
// Long lines of an imported grammar, wrapped so that a person can read and
// edit them: a line over the width is broken at its shallowest separators
// (`, ` or ` and `, outside strings), as many pieces to a line as fit, the
// continuation indented one step further; a piece still too long is broken
// at its own deeper separators. A trailing comment moves above the code.
// Lines without such separators, and comment lines, stay as they are.
#include <cstddef>
#include <string>

namespace g2d::import {

std::string wrapLongLines(const std::string& text, std::size_t width = 100);

}  // namespace g2d::import
