#pragma once
// Names for the imported grammar: the tool's free-form names (production
// titles, labels) as g2d identifiers that collide with nothing.

#include <set>
#include <string>
#include <string_view>

namespace g2d::import {

// "Add Brush Strokes" → "AddBrushStrokes" (rules).
std::string camelName(std::string_view text);
// "H-Floor" → "h_floor" (elements, constants).
std::string snakeName(std::string_view text);
// g2d's keywords and built-in names, which a grammar's names must avoid.
bool isReserved(std::string_view name);

// Hands out names, each once: "floor", then "floor2", "floor3", …
class NameSet {
public:
    std::string take(const std::string& wanted);
    bool has(const std::string& name) const { return taken_.count(name) != 0; }
    void reserve(const std::string& name) { taken_.insert(name); }

private:
    std::set<std::string> taken_;
};

}  // namespace g2d::import
