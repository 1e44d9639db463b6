#pragma once
// What a drawing shows, decided once for both back ends: every live face,
// then every live edge, then every live node, each in id order. An item's properties are its
// kind's style (`kindStyle` adds them, in declaration order), then the
// element's own style assignments, each replacing a property of the same
// name or, if none, appended. Enum values print by their value's name.
#include <functional>
#include <string>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/svg_writer.hpp"

namespace g2d::rt {

// Adds the style properties of kind `kind` to `item` (whose class, id and
// positions are set).
using KindStyle = std::function<void(DrawItem& item, int kind)>;

// The item of one live element, made in `item` (whose storage is reused:
// outputs make items one at a time).
void drawItem(const Graph& g, ElemClass cls, std::uint32_t id, const std::vector<std::vector<std::string>>& enumValueNames,
              const KindStyle& kindStyle, DrawItem& item);

std::vector<DrawItem> drawItems(const Graph& g, const std::vector<std::vector<std::string>>& enumValueNames,
                                const KindStyle& kindStyle);

// Every live element's item, made by `make` (the small pages that need all at once).
std::vector<DrawItem> drawItems(const Graph& g, const ItemMaker& make);

}  // namespace g2d::rt
