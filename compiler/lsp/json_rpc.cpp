#include "lsp/json_rpc.hpp"

#include <algorithm>
#include <istream>
#include <ostream>

namespace g2d::lsp {

std::optional<nlohmann::json> readMessage(std::istream& in) {
    std::size_t length = 0;
    bool haveLength = false;
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) {
            if (haveLength) break;
            continue;  // stray blank line between messages
        }
        const std::string key = "Content-Length:";
        if (line.compare(0, key.size(), key) == 0) {
            try {
                length = std::stoul(line.substr(key.size()));
                haveLength = true;
            } catch (const std::exception&) {
                haveLength = false;
            }
        }
    }
    if (!haveLength || !in || length > kMaxMessageBytes) return std::nullopt;
    // Read as the bytes come: a header may claim more than the stream holds.
    std::string body;
    char chunk[65536];
    while (body.size() < length) {
        in.read(chunk, static_cast<std::streamsize>(std::min(sizeof chunk, length - body.size())));
        if (in.gcount() <= 0) return std::nullopt;
        body.append(chunk, static_cast<std::size_t>(in.gcount()));
    }
    return nlohmann::json::parse(body, nullptr, /*allow_exceptions=*/false);
}

void writeMessage(std::ostream& out, const nlohmann::json& message) {
    const std::string body = message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    out << "Content-Length: " << body.size() << "\r\n\r\n" << body;
    out.flush();
}

}  // namespace g2d::lsp
