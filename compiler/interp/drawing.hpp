#pragma once
// Turns the derived graph into what the runtime's SVG and JSON writers take:
// each element's style resolved (kind defaults, then its own overrides).
#include <vector>

#include "g2d/json_writer.hpp"
#include "g2d/svg_writer.hpp"
#include "interp/program_state.hpp"

namespace g2d::interp {

std::vector<rt::DrawItem> drawItems(const rt::Graph& g, const ProgramState& st);
// One element's item (`enumNames`: each enum's value names).
void drawItem(const rt::Graph& g, const ProgramState& st, const std::vector<std::vector<std::string>>& enumNames,
              rt::ElemClass cls, std::uint32_t id, rt::DrawItem& out);
rt::JsonSchema jsonSchema(const ir::Program& prog);

}  // namespace g2d::interp
