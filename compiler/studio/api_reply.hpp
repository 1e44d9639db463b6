#pragma once
// An API answer: an HTTP status and a body, JSON unless it is a file the
// page downloads.
#include <string>

#include <nlohmann/json.hpp>

namespace g2d::studio {

struct ApiReply {
    int status = 200;
    std::string body;   // JSON, or a file's bytes
    std::string mediaType = "application/json";
};

inline ApiReply jsonReply(int status, const nlohmann::json& j) {
    return {status, j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)};
}

// {"status": "error", "message": …}
inline ApiReply errorReply(int status, const std::string& message) {
    return jsonReply(status, {{"status", "error"}, {"message", message}});
}

}  // namespace g2d::studio
