#pragma once
// JSON-RPC 2.0 messages framed as the Language Server Protocol frames them
// over stdio: `Content-Length: N` headers, a blank line, N bytes of JSON.
#include <iosfwd>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace g2d::lsp {

// The next message, or nothing at the end of the input. A body that is not
// JSON yields a null json value (the server answers with a parse error).
std::optional<nlohmann::json> readMessage(std::istream& in);
void writeMessage(std::ostream& out, const nlohmann::json& message);

}  // namespace g2d::lsp
