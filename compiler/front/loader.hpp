#pragma once
// Reads a grammar file and, recursively, the files it imports.
#include <optional>
#include <string>
#include <vector>

#include "ast/ast.hpp"
#include "diag/diagnostic.hpp"

namespace g2d {

struct LoadOptions {
    std::vector<std::string> importDirs;          // searched after the importing file's folder
    std::size_t maxFileBytes = 8u << 20;
};

// The folders `import` searches by default: $G2D_STDLIB (if set), the source
// tree's stdlib/ (for a build tree), and the installed share/g2d/stdlib.
std::vector<std::string> defaultImportDirs();

// Where `import "name"` in a file of folder `fromDir` refers to: the folder
// first, then `options.importDirs`; nothing if no such file exists.
std::optional<std::string> resolveImport(const std::string& name, const std::string& fromDir,
                                         const LoadOptions& options);

// Loads `path` and its imports. On success `out` holds the parsed files in
// dependency order, the main file last. Returns false if anything failed
// (diagnostics say what).
bool loadGrammar(const std::string& path, const LoadOptions& options, SourceManager& sm, Diagnostics& diags,
                 std::vector<ast::Program>& out);

}  // namespace g2d
