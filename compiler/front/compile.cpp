#include "front/compile.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "parse/parser.hpp"
#include "sema/sema.hpp"

namespace g2d {

namespace fs = std::filesystem;

namespace {

std::optional<ir::Program> analyzeAll(const std::vector<ast::Program>& imported, const ast::Program* main,
                                      Diagnostics& diags) {
    std::vector<const ast::Program*> ptrs;
    for (const auto& p : imported) ptrs.push_back(&p);
    if (main) ptrs.push_back(main);
    return analyze(ptrs, diags);
}

}  // namespace

CompileResult compileFile(const std::string& path, const LoadOptions& options) {
    CompileResult r;
    std::vector<ast::Program> programs;
    if (loadGrammar(path, options, r.sources, r.diags, programs)) r.program = analyzeAll(programs, nullptr, r.diags);
    r.syntax = std::move(programs);
    return r;
}

CompileResult compileSource(const std::string& path, const std::string& text, const LoadOptions& options) {
    CompileResult r;
    FileId id = r.sources.add(path, text);
    auto main = parseFile(r.sources, id, r.diags);
    if (!main) return r;
    std::vector<ast::Program> imported;
    bool ok = true;
    for (const auto& d : main->decls) {
        const auto* imp = std::get_if<ast::ImportDecl>(&d.decl);
        if (!imp) continue;
        const auto resolved = resolveImport(imp->path, fs::path(path).parent_path().string(), options);
        if (!resolved) {
            r.diags.error(imp->span, "cannot find imported file `" + imp->path +
                                         "` (looked next to the importing file and in the standard library)");
            ok = false;
            continue;
        }
        ok = loadGrammar(*resolved, options, r.sources, r.diags, imported) && ok;
    }
    if (ok) r.program = analyzeAll(imported, &*main, r.diags);
    r.syntax = std::move(imported);
    r.syntax.push_back(std::move(*main));
    return r;
}

CompileResult compileAndReport(const std::string& path) {
    LoadOptions load;
    load.importDirs = defaultImportDirs();
    CompileResult compiled = compileFile(path, load);
    const bool color = isatty(STDERR_FILENO) && !std::getenv("NO_COLOR");
    for (const auto& d : compiled.diags.sorted()) std::fputs(renderText(d, compiled.sources, color).c_str(), stderr);
    return compiled;
}

}  // namespace g2d
