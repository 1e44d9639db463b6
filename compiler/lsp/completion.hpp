#pragma once
// What to offer at a place in a grammar's text: after `x.`, x's attributes
// and the facts of its class; elsewhere, the names in scope there, the
// built-ins and the keywords. One list for the language server and the
// studio's editor.
#include <cstdint>
#include <string>
#include <vector>

#include "lsp/symbol_index.hpp"

namespace g2d::lsp {

struct CompletionItem {
    std::string label;
    int kind = 6;         // the LSP's CompletionItemKind
    std::string detail;   // what it is: a type, a signature, "keyword"
};

// At (line, col) of `file` (1-based, col in code points); `receiver` is `x`
// when the place follows `x.`.
std::vector<CompletionItem> completionsAt(const SymbolIndex& index, FileId file, std::uint32_t line, std::uint32_t col,
                                          const std::string& receiver);

}  // namespace g2d::lsp
