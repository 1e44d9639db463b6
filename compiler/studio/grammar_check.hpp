#pragma once
// `g2d check` for text the page holds: the same diagnostics, as data (the
// objects of `g2d check --diagnostics-format json`).
#include <string>

#include <nlohmann/json.hpp>

#include "front/compile.hpp"

namespace g2d::studio {

// The import folders `g2d check` searches, and its limits.
LoadOptions studioLoadOptions();

// Compiles `text` as the file `path` (imports resolve beside it).
CompileResult compileText(const std::string& path, const std::string& text);

// Every diagnostic of `compiled`, sorted as `g2d check` prints them.
nlohmann::json diagnosticsJson(const CompileResult& compiled);

// {"status": "ok" | "invalid", "diagnostics": [...]}
nlohmann::json checkText(const std::string& path, const std::string& text);

// The files `path`'s grammar imports as loaded from disk: [{"name", "text"}].
nlohmann::json importedFiles(const std::string& path);

}  // namespace g2d::studio
