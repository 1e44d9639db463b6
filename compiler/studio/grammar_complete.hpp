#pragma once
// Completion for the page's editor: the language server's list
// (lsp/completion.hpp) at a place in the text the page holds.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace g2d::studio {

// {"items": [{"label", "kind", "detail"}]} at `line` (1-based) and
// `character` (0-based, in UTF-16 units as the browser counts) of `text`,
// compiled as the file `path`.
nlohmann::json completeText(const std::string& path, const std::string& text, std::uint32_t line, std::uint32_t character);

}  // namespace g2d::studio
