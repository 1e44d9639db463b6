#pragma once
// Diagnostics are plain data produced by every stage and rendered once.
#include <string>
#include <vector>

#include "diag/source.hpp"

namespace g2d {

enum class Severity { Error, Warning, Note };

struct Diagnostic {
    Severity severity = Severity::Error;
    Span span;
    std::string message;
    struct Note { Span span; std::string message; };
    std::vector<Note> notes;
};

class Diagnostics {
public:
    Diagnostic& error(Span span, std::string message);
    Diagnostic& warning(Span span, std::string message);
    const std::vector<Diagnostic>& all() const { return list_; }
    std::size_t errorCount() const;
    bool hasErrors() const { return errorCount() > 0; }
    // Stable order for output: by file, line, column (insertion order on ties).
    std::vector<Diagnostic> sorted() const;

private:
    std::vector<Diagnostic> list_;
};

// `file:line:col: error: message`, the source line and a caret under the span.
std::string renderText(const Diagnostic& d, const SourceManager& sm, bool color = false);
// One JSON array of all diagnostics, for editors.
std::string renderJson(const std::vector<Diagnostic>& ds, const SourceManager& sm);

}  // namespace g2d
