#include "diag/diagnostic.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "g2d/source_excerpt.hpp"

namespace g2d {

Diagnostic& Diagnostics::error(Span span, std::string message) {
    list_.push_back(Diagnostic{Severity::Error, span, std::move(message), {}});
    return list_.back();
}

Diagnostic& Diagnostics::warning(Span span, std::string message) {
    list_.push_back(Diagnostic{Severity::Warning, span, std::move(message), {}});
    return list_.back();
}

std::size_t Diagnostics::errorCount() const {
    return static_cast<std::size_t>(std::count_if(list_.begin(), list_.end(), [](const Diagnostic& d) {
        return d.severity == Severity::Error;
    }));
}

std::vector<Diagnostic> Diagnostics::sorted() const {
    std::vector<Diagnostic> out = list_;
    std::stable_sort(out.begin(), out.end(), [](const Diagnostic& a, const Diagnostic& b) {
        if (a.span.file != b.span.file) return a.span.file < b.span.file;
        if (a.span.line != b.span.line) return a.span.line < b.span.line;
        return a.span.col < b.span.col;
    });
    return out;
}

namespace {

const char* severityName(Severity s) {
    switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
    }
    return "error";
}

void renderOne(std::string& out, Severity sev, const Span& span, const std::string& message,
               const SourceManager& sm, bool color) {
    const char* bold = color ? "\x1b[1m" : "";
    const char* reset = color ? "\x1b[0m" : "";
    const char* sevColor = !color ? "" : sev == Severity::Error ? "\x1b[1;31m"
                                     : sev == Severity::Warning ? "\x1b[1;35m" : "\x1b[1;36m";
    if (span.valid() && span.file < sm.size()) {
        out += bold + sm.file(span.file).path + ":" + std::to_string(span.line) + ":" +
               std::to_string(span.col) + ":" + reset + " ";
    } else if (span.file != kNoFile && span.file < sm.size()) {
        out += bold + sm.file(span.file).path + ":" + reset + " ";
    }
    out += std::string(sevColor) + severityName(sev) + ":" + reset + " " + message + "\n";
    if (!span.valid() || span.file >= sm.size()) return;
    const rt::Excerpt ex =
        rt::excerptLine(sm.lineText(span.file, span.line), span.col, span.endLine == span.line ? span.endCol : 0);
    out += "  " + ex.line + "\n";
    out += "  " + std::string(ex.pad, ' ') + sevColor + "^" + std::string(ex.width - 1, '~') + reset + "\n";
}

}  // namespace

std::string renderText(const Diagnostic& d, const SourceManager& sm, bool color) {
    std::string out;
    renderOne(out, d.severity, d.span, d.message, sm, color);
    for (const auto& n : d.notes) renderOne(out, Severity::Note, n.span, n.message, sm, color);
    return out;
}

std::string renderJson(const std::vector<Diagnostic>& ds, const SourceManager& sm) {
    auto spanJson = [&](const Span& s) {
        nlohmann::json j;
        j["file"] = (s.file != kNoFile && s.file < sm.size()) ? sm.file(s.file).path : "";
        j["line"] = s.line;
        j["column"] = s.col;
        j["end_line"] = s.endLine ? s.endLine : s.line;
        j["end_column"] = s.endCol ? s.endCol : s.col + 1;
        return j;
    };
    nlohmann::json arr = nlohmann::json::array();
    for (const auto& d : ds) {
        nlohmann::json j = spanJson(d.span);
        j["severity"] = severityName(d.severity);
        j["message"] = d.message;
        nlohmann::json notes = nlohmann::json::array();
        for (const auto& n : d.notes) {
            nlohmann::json nj = spanJson(n.span);
            nj["message"] = n.message;
            notes.push_back(nj);
        }
        j["notes"] = notes;
        arr.push_back(j);
    }
    // Invalid UTF-8 never reaches here (the loader rejects it), but be safe.
    return arr.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace g2d
