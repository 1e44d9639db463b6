#pragma once
// `g2d show`: every production drawn as its mother graph beside each
// daughter graph, as in the thesis's production diagrams — kept elements in
// orange (the mapping is by name, and kept nodes keep their place), deleted
// ones dashed red, new ones green, negative conditions dashed grey — with
// the rule's options, its conditions and each daughter's weight; the axiom
// first. As one SVG, or as an HTML page holding it.
#include <string>

#include "diag/source.hpp"
#include "ir/ir.hpp"

namespace g2d::show {

std::string productionsSvg(const ir::Program& prog, const SourceManager& sources, const std::string& title);
std::string productionsPage(const ir::Program& prog, const SourceManager& sources, const std::string& title);

}  // namespace g2d::show
