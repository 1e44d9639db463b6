#include "studio/grammar_complete.hpp"

#include <sstream>

#include "lsp/completion.hpp"
#include "lsp/positions.hpp"
#include "lsp/symbol_index.hpp"
#include "studio/grammar_check.hpp"

namespace g2d::studio {

nlohmann::json completeText(const std::string& path, const std::string& text, std::uint32_t line, std::uint32_t character) {
    nlohmann::json items = nlohmann::json::array();
    std::istringstream lines(text);
    std::string lineText;
    for (std::uint32_t i = 0; i < line && std::getline(lines, lineText); ++i) {}
    if (line == 0 || !lines && lineText.empty()) return {{"items", items}};
    if (!lineText.empty() && lineText.back() == '\r') lineText.pop_back();
    // Names come from what parsed, so completion works while the text has errors.
    const CompileResult compiled = compileText(path, text);
    const lsp::SymbolIndex index(compiled.syntax, compiled.sources);
    const std::uint32_t col = lsp::codePointColumn(lineText, character);
    std::uint32_t start = col;
    const std::string word = lsp::identifierAt(lineText, col, &start);
    const std::uint32_t dotCol = word.empty() ? col : start;   // a `.` just before the word (or the cursor)
    std::string receiver;
    if (dotCol >= 2 && dotCol - 2 < lineText.size() && lineText[dotCol - 2] == '.') receiver = lsp::identifierAt(lineText, dotCol - 2);
    constexpr FileId kMainFile = 0;   // the text is the first file the compiler reads
    for (const auto& item : lsp::completionsAt(index, kMainFile, line, col, receiver))
        items.push_back({{"label", item.label}, {"kind", item.kind}, {"detail", item.detail}});
    return {{"items", items}};
}

}  // namespace g2d::studio
