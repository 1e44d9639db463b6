#include "infer/label_colours.hpp"

#include <iterator>

namespace g2d::infer {

namespace {
// Areas without a colour of their own: light, distinct, and the same for the same index every time.
const char* const kPalette[] = {"#a6cee3", "#b2df8a", "#fb9a99", "#fdbf6f", "#cab2d6", "#ffff99", "#8dd3c7", "#bebada"};
}  // namespace

std::string areaColour(const LabelledExample& ex, int area) {
    const std::string& own = ex.shape.areas[static_cast<std::size_t>(area)].color;
    return own.empty() ? kPalette[static_cast<std::size_t>(area) % std::size(kPalette)] : own;
}

std::string edgeColour(const LabelledExample& ex, int label) {
    const EdgeLabel& l = ex.labels[static_cast<std::size_t>(label)];
    const std::string& own = ex.shape.brushes[static_cast<std::size_t>(l.brush)].color;
    return own.empty() ? "#202020" : own;
}

}  // namespace g2d::infer
