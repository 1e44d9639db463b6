// The language server on a session of JSON-RPC messages built from the
// bytes: the document (the bytes up to the first NUL, or all of them), then
// edits with ranges anywhere (past the end, inside a character, backwards),
// requests at any position, messages with parameters of the wrong shape and
// bodies that are not JSON. Every request must get exactly one answer, every
// message the server writes must be framed JSON, and the session must end
// as the client ends it. A first byte 0xff instead sends the rest unframed.
#include <map>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "byte_source.hpp"
#include "driver/big_stack.hpp"
#include "fuzz_checks.hpp"
#include "lsp/json_rpc.hpp"
#include "lsp/server.hpp"
#include "reader_checks.hpp"

namespace g2d::fuzz {

namespace {

using nlohmann::json;

const char* const kUri = "file:///nonexistent-g2d-fuzz/doc.g2d";

std::string framed(const std::string& body) { return "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body; }

// A position: mostly inside the document, sometimes anywhere a client could send.
json position(ByteSource& in) {
    switch (in.byte() % 8) {
    case 0: return json{{"line", static_cast<std::int64_t>(in.word()) - 0x80000000LL}, {"character", in.below(200)}};
    case 1: return json{{"line", in.below(40)}, {"character", static_cast<std::int64_t>(in.word())}};
    case 2: return json{{"line", -1}, {"character", -1}};
    case 3: return json{{"line", "1"}, {"character", 2.5}};
    default: return json{{"line", in.below(40)}, {"character", in.below(80)}};
    }
}

// Parameters in the shape LSP asks for, or (sometimes) not.
json textDocument(ByteSource& in) {
    switch (in.byte() % 16) {
    case 0: return json{{"uri", 7}};
    case 1: return json("doc");
    case 2: return json{{"uri", "file:///nonexistent-g2d-fuzz/other.g2d"}};
    default: return json{{"uri", kUri}};
    }
}

class Session {
public:
    explicit Session(ByteSource& ops) : ops_(ops) {}

    void request(const std::string& method, const json& params) {
        const int id = nextId_++;
        expected_[id] = method;
        send(json{{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", params}});
    }
    void notify(const std::string& method, const json& params) {
        send(json{{"jsonrpc", "2.0"}, {"method", method}, {"params", params}});
    }
    // As a client would: JSON text is UTF-8, so bytes that are not become U+FFFD.
    void send(const json& message) { stream_ += framed(message.dump(-1, ' ', false, json::error_handler_t::replace)); }
    void sendRaw(const std::string& body) { stream_ += framed(body); }

    void operation(const std::string& document) {
        switch (ops_.byte() % 10) {
        case 0:
            notify("textDocument/didChange", json{{"textDocument", textDocument(ops_)},
                                                  {"contentChanges", json::array({json{{"text", ops_.text(200)}}})}});
            break;
        case 1:
        case 2: {
            json change{{"range", json{{"start", position(ops_)}, {"end", position(ops_)}}}, {"text", ops_.text(40)}};
            notify("textDocument/didChange", json{{"textDocument", textDocument(ops_)}, {"contentChanges", json::array({change})}});
            break;
        }
        case 3: request("textDocument/hover", json{{"textDocument", textDocument(ops_)}, {"position", position(ops_)}}); break;
        case 4: request("textDocument/completion", json{{"textDocument", textDocument(ops_)}, {"position", position(ops_)}}); break;
        case 5: request("textDocument/definition", json{{"textDocument", textDocument(ops_)}, {"position", position(ops_)}}); break;
        case 6: request("textDocument/documentSymbol", json{{"textDocument", textDocument(ops_)}}); break;
        case 7:
            notify("textDocument/didClose", json{{"textDocument", json{{"uri", kUri}}}});
            notify("textDocument/didOpen", json{{"textDocument", json{{"uri", kUri}, {"text", document}}}});
            break;
        case 8: {
            // A message of the wrong shape: a method that is no string, params that are no object, an id that is an object.
            const int id = nextId_++;
            switch (ops_.byte() % 4) {
            case 0: send(json{{"jsonrpc", "2.0"}, {"id", id}, {"method", 42}}); expected_[id] = "42"; break;
            case 1: send(json{{"jsonrpc", "2.0"}, {"id", id}, {"method", "textDocument/hover"}, {"params", 3}}); expected_[id] = "hover"; break;
            case 2: send(json{{"jsonrpc", "2.0"}, {"id", json{{"a", 1}}}, {"method", "textDocument/hover"}}); break;
            default: send(json::array({1, 2})); break;
            }
            break;
        }
        // A body that is not JSON (never a message by chance: JSON cannot start with "]").
        default: sendRaw("]" + ops_.text(60)); break;
        }
    }

    std::string stream_;
    std::map<int, std::string> expected_;   // request id -> method

private:
    ByteSource& ops_;
    int nextId_ = 1;
};

void checkAnswers(const std::string& output, const std::map<int, std::string>* expected) {
    std::istringstream out(output);
    std::map<int, int> answers;
    while (auto message = lsp::readMessage(out)) {
        if (!message->is_object()) violated("the server wrote a message that is not a JSON object");
        if (message->contains("id") && (*message)["id"].is_number_integer()) ++answers[(*message)["id"].get<int>()];
    }
    if (!expected) return;
    for (const auto& [id, method] : *expected)
        if (answers[id] != 1)
            violated("request " + std::to_string(id) + " (" + method + ") got " + std::to_string(answers[id]) + " answers");
}

}  // namespace

void checkLanguageServer(const std::uint8_t* data, std::size_t size) {
    runWithBigStack([&] {
        std::ostringstream out;
        int code = 0;
        if (size > 0 && data[0] == 0xff) {
            std::istringstream in(std::string(reinterpret_cast<const char*>(data + 1), size - 1));
            try {
                code = lsp::runLanguageServer(in, out);
            } catch (const std::exception& e) {
                violated(std::string("the server threw: ") + e.what());
            }
            if (code != 0 && code != 1) violated("exit code " + std::to_string(code));
            checkAnswers(out.str(), nullptr);
            return 0;
        }
        const std::string bytes(reinterpret_cast<const char*>(data), size);
        const std::size_t nul = bytes.find('\0');
        const std::string document = bytes.substr(0, nul);
        // Without a NUL, the document's own bytes choose the operations.
        ByteSource ops = nul == std::string::npos ? ByteSource(data, size)
                                                  : ByteSource(data + nul + 1, size - nul - 1);
        Session session(ops);
        session.request("initialize", json{{"processId", nullptr}, {"capabilities", json::object()}});
        session.notify("initialized", json::object());
        session.notify("textDocument/didOpen", json{{"textDocument", json{{"uri", kUri}, {"languageId", "g2d"}, {"version", 1}, {"text", document}}}});
        for (int i = 0; i < 24 && !ops.empty(); ++i) session.operation(document);
        session.request("textDocument/documentSymbol", json{{"textDocument", json{{"uri", kUri}}}});
        session.request("shutdown", nullptr);
        session.notify("exit", nullptr);
        std::istringstream in(session.stream_);
        try {
            code = lsp::runLanguageServer(in, out);
        } catch (const std::exception& e) {
            violated(std::string("the server threw: ") + e.what());
        }
        if (code != 0) violated("the server did not end with 0 after shutdown and exit");
        checkAnswers(out.str(), &session.expected_);
        return 0;
    });
}

}  // namespace g2d::fuzz
