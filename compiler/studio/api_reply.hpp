#pragma once
// An API answer: an HTTP status and a body, JSON unless it is a file the
// page downloads.
#include <string>

#include <nlohmann/json.hpp>

namespace g2d::studio {

// cpp-httplib compresses an answer whose type is exactly application/json (or text/…, SVG, …)
// when the browser accepts Brotli, at a cost of 200 ms for a 100 kB picture and seconds
// for the page's script. On loopback that is time lost, so the studio's types are ones it
// leaves alone: with a charset, or of another family.
inline constexpr const char* kJsonType = "application/json; charset=utf-8";

struct ApiReply {
    int status = 200;
    std::string body;   // JSON, or a file's bytes
    std::string mediaType = kJsonType;
};

inline ApiReply jsonReply(int status, const nlohmann::json& j) {
    return {status, j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)};
}

// {"status": "error", "message": …}
inline ApiReply errorReply(int status, const std::string& message) {
    return jsonReply(status, {{"status", "error"}, {"message", message}});
}

}  // namespace g2d::studio
