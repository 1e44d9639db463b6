#include "g2d/grammar_run.hpp"

#include "g2d/draw_items.hpp"
#include "g2d/graph.hpp"

namespace g2d::rt {

// Out of line: grammar_run.hpp only declares DrawItem and Graph.
std::vector<DrawItem> GrammarRun::drawItems() {
    return rt::drawItems(graph(), [this](ElemClass cls, std::uint32_t id, DrawItem& out) { drawItem(cls, id, out); });
}

}  // namespace g2d::rt
