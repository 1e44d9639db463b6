#pragma once
// The whole front end for one grammar file: load, parse, analyse.
#include <optional>
#include <string>

#include "ast/ast.hpp"
#include "diag/diagnostic.hpp"
#include "front/loader.hpp"
#include "ir/ir.hpp"

namespace g2d {

struct CompileResult {
    SourceManager sources;
    Diagnostics diags;
    std::optional<ir::Program> program;   // present when there are no errors
    std::vector<ast::Program> syntax;     // every file that parsed, the main file last (for editors)
};

CompileResult compileFile(const std::string& path, const LoadOptions& options);
// For tests and editors: compiles source text given directly (imports resolve
// relative to `path`'s folder).
CompileResult compileSource(const std::string& path, const std::string& text, const LoadOptions& options);

// For the commands that compile one grammar (run, build, emit-cpp, show):
// compiles `path` with the default import folders and prints its
// diagnostics to stderr (in colour on a terminal, unless NO_COLOR is set).
CompileResult compileAndReport(const std::string& path);

}  // namespace g2d
