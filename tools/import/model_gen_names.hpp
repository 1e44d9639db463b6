#pragma once
// Names for the imported grammar: the tool's free-form names (production
// titles, labels) as g2d identifiers that collide with nothing.

#include <set>
#include <string>
#include <string_view>

namespace g2d::import {

// [A-Za-z_][A-Za-z0-9_]*: a g2d name's syntax.
bool isIdentifier(std::string_view text);
// "Add Brush Strokes" → "AddBrushStrokes" (rules).
std::string camelName(std::string_view text);
// "H-Floor" → "h_floor" (elements, constants).
std::string snakeName(std::string_view text);
// Hands out names, each once: "floor", then "floor2", "floor3", …; a
// reserved one (a keyword, a built-in: `reserved`) gets a `_` first.
class NameSet {
public:
    explicit NameSet(const std::set<std::string>& reserved) : reserved_(&reserved) {}
    std::string take(const std::string& wanted);
    bool has(const std::string& name) const { return taken_.count(name) != 0; }
    void reserve(const std::string& name) { taken_.insert(name); }

private:
    const std::set<std::string>* reserved_;
    std::set<std::string> taken_;
};

}  // namespace g2d::import
