#include "studio/grammar_check.hpp"

#include "front/loader.hpp"

namespace g2d::studio {

LoadOptions studioLoadOptions() {
    LoadOptions options;
    options.importDirs = defaultImportDirs();
    return options;
}

CompileResult compileText(const std::string& path, const std::string& text) {
    return compileSource(path, text, studioLoadOptions());
}

nlohmann::json diagnosticsJson(const CompileResult& compiled) {
    return nlohmann::json::parse(renderJson(compiled.diags.sorted(), compiled.sources));
}

nlohmann::json checkText(const std::string& path, const std::string& text) {
    const CompileResult compiled = compileText(path, text);
    return {{"status", compiled.program ? "ok" : "invalid"}, {"diagnostics", diagnosticsJson(compiled)}};
}

nlohmann::json importedFiles(const std::string& path) {
    nlohmann::json files = nlohmann::json::array();
    if (path.empty()) return files;
    SourceManager sources;
    Diagnostics diags;
    std::vector<ast::Program> programs;
    loadGrammar(path, studioLoadOptions(), sources, diags, programs);   // what loaded, even with errors
    for (FileId id = 0; id < sources.size(); ++id) {
        const auto& file = sources.file(id);
        if (file.path == path) continue;
        files.push_back({{"name", file.path}, {"text", file.text}});
    }
    return files;
}

}  // namespace g2d::studio
