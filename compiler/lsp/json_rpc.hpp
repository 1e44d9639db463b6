#pragma once
// JSON-RPC 2.0 messages framed as the Language Server Protocol frames them
// over stdio: `Content-Length: N` headers, a blank line, N bytes of JSON.
#include <iosfwd>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace g2d::lsp {

// The next message, or nothing at the end of the input (or a header that
// claims more than kMaxMessageBytes, or more than the input holds). A body
// that is not JSON yields a discarded json value (the server answers with a
// parse error).
inline constexpr std::size_t kMaxMessageBytes = std::size_t{1} << 28;
std::optional<nlohmann::json> readMessage(std::istream& in);
void writeMessage(std::ostream& out, const nlohmann::json& message);

}  // namespace g2d::lsp
