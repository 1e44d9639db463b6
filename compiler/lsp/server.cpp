#include "lsp/server.hpp"

#include <filesystem>
#include <istream>
#include <map>
#include <memory>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "front/compile.hpp"
#include "lsp/json_rpc.hpp"
#include "lsp/completion.hpp"
#include "lsp/positions.hpp"
#include "lsp/symbol_index.hpp"
#include "sema/builtins.hpp"

namespace g2d::lsp {

namespace {

using json = nlohmann::json;

constexpr int kMethodNotFound = -32601, kParseError = -32700, kInvalidParams = -32602, kInvalidRequest = -32600;

// Parameters of the right JSON type but outside what LSP allows.
struct BadParams : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// An LSP `uinteger` (0 to 2^31 - 1).
std::uint32_t uinteger(const json& value, const char* what) {
    if (!value.is_number_integer() || value.get<std::int64_t>() < 0 || value.get<std::int64_t>() > 0x7fffffff)
        throw BadParams(std::string(what) + " must be an integer from 0 to 2^31 - 1");
    return value.get<std::uint32_t>();
}

struct Document {
    std::string uri, path, text;
    std::vector<std::string> lines;
    std::unique_ptr<CompileResult> compiled;
    std::unique_ptr<SymbolIndex> index;
};

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::string line;
    std::istringstream in(text);
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    if (lines.empty()) lines.emplace_back();
    return lines;
}

int symbolKindNumber(SymbolKind k) {   // LSP SymbolKind
    switch (k) {
    case SymbolKind::NodeKind: return 5;       // Class
    case SymbolKind::EdgeKind: return 23;      // Struct
    case SymbolKind::FaceKind: return 23;      // Struct
    case SymbolKind::Face: return 13;          // Variable
    case SymbolKind::Attribute: return 7;      // Property
    case SymbolKind::Rule: return 6;           // Method
    case SymbolKind::Function: return 12;      // Function
    case SymbolKind::Const: return 14;         // Constant
    case SymbolKind::Enum: return 10;          // Enum
    case SymbolKind::Enumerator: return 22;    // EnumMember
    case SymbolKind::Import: return 2;         // Module
    default: return 13;                        // Variable
    }
}

class Server {
public:
    explicit Server(std::ostream& out) : out_(out) {}

    // Returns false once the client said `exit`.
    bool handle(const json& message) {
        if (!message.is_object()) {
            reply(nullptr, json(), json{{"code", kParseError}, {"message", "not a JSON-RPC message"}});
            return true;
        }
        const json id = message.contains("id") ? message["id"] : json();
        const bool isRequest = message.contains("id");
        const auto methodField = message.find("method");
        if (methodField == message.end() || !methodField->is_string()) {
            // A response (the server asks nothing) is ignored; anything else is no request.
            if (isRequest && !message.contains("result") && !message.contains("error"))
                reply(id, json(), json{{"code", kInvalidRequest}, {"message", "a request needs a method name (a string)"}});
            return true;
        }
        const std::string method = methodField->get<std::string>();
        const json params = message.contains("params") ? message["params"] : json::object();
        try {
            if (method == "initialize") return reply(id, initializeResult()), true;
            if (method == "shutdown") return shutdown_ = true, reply(id, nullptr), true;
            if (method == "exit") return false;
            if (method == "textDocument/didOpen") {
                const auto& d = params.at("textDocument");
                open(d.at("uri").get<std::string>(), d.at("text").get<std::string>());
            } else if (method == "textDocument/didChange") {
                change(params.at("textDocument").at("uri").get<std::string>(), params.at("contentChanges"));
            } else if (method == "textDocument/didClose") {
                const std::string uri = params.at("textDocument").at("uri").get<std::string>();
                docs_.erase(uri);
                notify("textDocument/publishDiagnostics", json{{"uri", uri}, {"diagnostics", json::array()}});
            } else if (method == "textDocument/hover") {
                reply(id, hover(params));
            } else if (method == "textDocument/definition") {
                reply(id, definition(params));
            } else if (method == "textDocument/documentSymbol") {
                reply(id, documentSymbols(params));
            } else if (method == "textDocument/completion") {
                reply(id, completion(params));
            } else if (isRequest) {
                reply(id, json(), json{{"code", kMethodNotFound}, {"message", "g2d lsp does not handle " + method}});
            }
        } catch (const json::exception& e) {
            if (isRequest) reply(id, json(), json{{"code", kInvalidParams}, {"message", e.what()}});
        } catch (const BadParams& e) {
            if (isRequest) reply(id, json(), json{{"code", kInvalidParams}, {"message", e.what()}});
        }
        return true;
    }

    int exitCode() const { return shutdown_ ? 0 : 1; }

private:
    json initializeResult() const {
        return json{{"capabilities",
                     {{"textDocumentSync", 1},   // full text on every change
                      {"hoverProvider", true},
                      {"definitionProvider", true},
                      {"documentSymbolProvider", true},
                      {"completionProvider", {{"triggerCharacters", json::array({"."})}}}}},
                    {"serverInfo", {{"name", "g2d"}, {"version", "0.1.0"}}}};
    }

    void reply(const json& id, const json& result, const json& error = json()) {
        json m{{"jsonrpc", "2.0"}, {"id", id}};
        if (error.is_null()) m["result"] = result;
        else m["error"] = error;
        writeMessage(out_, m);
    }

    void notify(const std::string& method, const json& params) {
        writeMessage(out_, json{{"jsonrpc", "2.0"}, {"method", method}, {"params", params}});
    }

    // Full text, or (sent by clients that ignore the full sync the server
    // asks for) edits of ranges, applied in order.
    void change(const std::string& uri, const json& changes) {
        if (!changes.is_array()) throw BadParams("contentChanges must be a list");
        if (changes.empty()) return;
        const auto it = docs_.find(uri);
        std::string text = it == docs_.end() ? std::string() : it->second.text;
        for (const json& c : changes) {
            const std::string replacement = c.at("text").get<std::string>();
            if (!c.contains("range")) {
                text = replacement;
                continue;
            }
            const json& range = c.at("range");
            auto offset = [&](const json& at) {
                return byteOffset(text, uinteger(at.at("line"), "a range's line"), uinteger(at.at("character"), "a range's character"));
            };
            const std::size_t from = offset(range.at("start")), to = offset(range.at("end"));
            if (to < from) throw BadParams("a range must not end before it starts");
            text.replace(from, to - from, replacement);
        }
        open(uri, text);
    }

    void open(const std::string& uri, const std::string& text) {
        Document& d = docs_[uri];
        d.uri = uri;
        d.path = uriToPath(uri);
        d.text = text;
        d.lines = splitLines(text);
        LoadOptions options;
        options.importDirs = defaultImportDirs();
        d.compiled = std::make_unique<CompileResult>(compileSource(d.path, d.text, options));
        d.index = std::make_unique<SymbolIndex>(d.compiled->syntax, d.compiled->sources);
        publishDiagnostics(d);
    }

    // The document's own file is the first the compiler read.
    static constexpr FileId kMainFile = 0;

    json range(const Document& d, const Span& s) const {
        auto lineOf = [&](FileId f, std::uint32_t l) {
            return f == kMainFile ? (l >= 1 && l <= d.lines.size() ? d.lines[l - 1] : std::string())
                                  : d.compiled->sources.lineText(f, l);
        };
        if (!s.valid()) return json{{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 0}}}};
        const std::uint32_t endLine = s.endLine ? s.endLine : s.line;
        const std::uint32_t endCol = s.endCol && s.endLine ? s.endCol : s.col + 1;
        return json{{"start", {{"line", s.line - 1}, {"character", utf16Offset(lineOf(s.file, s.line), s.col)}}},
                    {"end", {{"line", endLine - 1}, {"character", utf16Offset(lineOf(s.file, endLine), endCol)}}}};
    }

    std::string uriOf(const Document& d, FileId file) const {
        return file == kMainFile ? d.uri : pathToUri(d.compiled->sources.file(file).path);
    }

    void publishDiagnostics(const Document& d) {
        json list = json::array();
        for (const auto& diag : d.compiled->diags.sorted()) {
            json item{{"severity", diag.severity == Severity::Error ? 1 : diag.severity == Severity::Warning ? 2 : 3},
                      {"source", "g2d"}};
            if (diag.span.file == kMainFile || diag.span.file == kNoFile) {
                item["range"] = range(d, diag.span);
                item["message"] = diag.message;
            } else {
                // In an imported file: shown on the first line, saying where.
                const auto& f = d.compiled->sources.file(diag.span.file);
                item["range"] = range(d, Span{});
                item["message"] = f.path + ":" + std::to_string(diag.span.line) + ":" + std::to_string(diag.span.col) +
                                  ": " + diag.message;
            }
            json related = json::array();
            for (const auto& note : diag.notes)
                if (note.span.valid())
                    related.push_back({{"location", {{"uri", uriOf(d, note.span.file)}, {"range", range(d, note.span)}}},
                                       {"message", note.message}});
            if (!related.empty()) item["relatedInformation"] = related;
            list.push_back(item);
        }
        notify("textDocument/publishDiagnostics", json{{"uri", d.uri}, {"diagnostics", list}});
    }

    // The document and the (line, column) of a request, in the compiler's terms.
    struct Place {
        const Document* doc = nullptr;
        std::uint32_t line = 0, col = 0;
        std::string word, receiver;   // the identifier there, and `x` in `x.word`
        std::uint32_t wordStart = 0;
    };

    Place place(const json& params) const {
        Place p;
        const auto it = docs_.find(params.at("textDocument").at("uri").get<std::string>());
        if (it == docs_.end()) return p;
        p.doc = &it->second;
        const json& position = params.at("position");
        p.line = uinteger(position.at("line"), "a position's line") + 1;
        const std::uint32_t character = uinteger(position.at("character"), "a position's character");
        if (p.line > p.doc->lines.size()) return p;
        const std::string& text = p.doc->lines[p.line - 1];
        p.col = codePointColumn(text, character);
        p.word = identifierAt(text, p.col, &p.wordStart);
        const std::uint32_t dotCol = p.word.empty() ? p.col : p.wordStart;   // a `.` just before the word (or the cursor)
        if (dotCol >= 2 && dotCol - 2 < text.size() && text[dotCol - 2] == '.') p.receiver = identifierAt(text, dotCol - 2);
        return p;
    }

    json hover(const json& params) const {
        const Place p = place(params);
        if (!p.doc || p.word.empty()) return nullptr;
        std::string markdown;
        if (const Symbol* s = p.doc->index->resolve(p.word, kMainFile, p.line, p.col, p.receiver)) {
            markdown = "**" + std::string(SymbolIndex::describe(s->kind)) + "** `" + s->name + "`";
            const std::string type = s->typeName.empty() ? inferredType(*p.doc, *s) : s->typeName;
            if (!type.empty()) markdown += ": `" + type + "`";
            if (!s->container.empty()) markdown += " (in `" + s->container + "`)";
            markdown += "\n\n```g2d\n" + s->declaration + "\n```";
        } else if (const auto* b = sema::findBuiltin(p.word)) {
            markdown = "**built-in function**\n\n```g2d\n" + b->signature + "\n```";
            if (sema::drawsRandom(*b)) markdown += "\n\nDraws from the run's seeded random generator.";
        } else {
            return nullptr;
        }
        Span at{kMainFile, p.line, p.wordStart, p.line, p.wordStart + static_cast<std::uint32_t>(p.word.size())};
        return json{{"contents", {{"kind", "markdown"}, {"value", markdown}}}, {"range", range(*p.doc, at)}};
    }

    // The type the checker gave a constant or a `let` written without one
    // (known when the grammar has no errors).
    static std::string inferredType(const Document& d, const Symbol& s) {
        const auto& prog = d.compiled->program;
        if (!prog) return "";
        if (s.kind == SymbolKind::Const)
            for (const auto& c : prog->consts)
                if (c.name == s.name) return ir::typeName(c.type, *prog);
        if (s.kind == SymbolKind::Let)
            for (const auto& r : prog->rules) {
                if (r.name != s.container) continue;
                for (const auto& l : r.lets)
                    if (l.name == s.name) return ir::typeName(l.value.type, *prog);
                for (const auto& daughter : r.daughters)
                    for (const auto& l : daughter.lets)
                        if (l.name == s.name) return ir::typeName(l.value.type, *prog);
            }
        return "";
    }

    json definition(const json& params) const {
        const Place p = place(params);
        if (!p.doc) return nullptr;
        // `import "file.g2d";`: the imported file.
        const std::string& text = p.line <= p.doc->lines.size() ? p.doc->lines[p.line - 1] : std::string();
        const auto q1 = text.find('"'), q2 = text.rfind('"');
        if (text.find("import") != std::string::npos && q1 != std::string::npos && q2 > q1 && p.col > q1 && p.col <= q2 + 1) {
            LoadOptions options;
            options.importDirs = defaultImportDirs();
            const auto found = resolveImport(text.substr(q1 + 1, q2 - q1 - 1),
                                             std::filesystem::path(p.doc->path).parent_path().string(), options);
            if (!found) return nullptr;
            return json{{"uri", pathToUri(*found)}, {"range", range(*p.doc, Span{})}};
        }
        if (p.word.empty()) return nullptr;
        const Symbol* s = p.doc->index->resolve(p.word, kMainFile, p.line, p.col, p.receiver);
        if (!s) return nullptr;
        return json{{"uri", uriOf(*p.doc, s->at.file)}, {"range", range(*p.doc, s->at)}};
    }

    json documentSymbols(const json& params) const {
        const auto it = docs_.find(params.at("textDocument").at("uri").get<std::string>());
        if (it == docs_.end()) return json::array();
        const Document& d = it->second;
        auto entry = [&](const Symbol& s) {
            return json{{"name", s.name},
                        {"detail", s.typeName.empty() ? std::string(SymbolIndex::describe(s.kind)) : s.typeName},
                        {"kind", symbolKindNumber(s.kind)},
                        {"range", range(d, s.at)},
                        {"selectionRange", range(d, s.at)},
                        {"children", json::array()}};
        };
        json out = json::array();
        for (const auto& s : d.index->all()) {
            if (s.at.file != kMainFile || s.scope.valid() || s.kind == SymbolKind::Attribute || s.kind == SymbolKind::Enumerator)
                continue;
            json top = entry(s);
            for (const auto& c : d.index->all()) {
                if (c.at.file != kMainFile || c.container != s.name) continue;
                const bool member = (c.kind == SymbolKind::Attribute && (s.kind == SymbolKind::NodeKind || s.kind == SymbolKind::EdgeKind || s.kind == SymbolKind::FaceKind)) ||
                                    (c.kind == SymbolKind::Enumerator && s.kind == SymbolKind::Enum) ||
                                    (c.scope.valid() && (s.kind == SymbolKind::Rule || s.kind == SymbolKind::Function));
                if (member) top["children"].push_back(entry(c));
            }
            out.push_back(top);
        }
        return out;
    }

    json completion(const json& params) const {
        const Place p = place(params);
        json items = json::array();
        if (!p.doc) return items;
        for (const auto& item : completionsAt(*p.doc->index, kMainFile, p.line, p.col, p.receiver))
            items.push_back(json{{"label", item.label}, {"kind", item.kind}, {"detail", item.detail}});
        return items;
    }

    std::ostream& out_;
    std::map<std::string, Document> docs_;
    bool shutdown_ = false;
};

}  // namespace

int runLanguageServer(std::istream& in, std::ostream& out) {
    Server server(out);
    while (auto message = readMessage(in))
        if (!server.handle(*message)) break;
    return server.exitCode();
}

}  // namespace g2d::lsp
