#include "studio/request_guard.hpp"

#include <algorithm>
#include <cctype>

namespace g2d::studio {

namespace {

std::string lowered(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// The names the studio answers to: it listens on 127.0.0.1 only.
bool ownHost(const std::string& host, int port) {
    const std::string p = ":" + std::to_string(port);
    const std::string h = lowered(host);
    return h == "127.0.0.1" + p || h == "localhost" + p;
}

bool ownOrigin(const std::string& origin, int port) {
    const std::string o = lowered(origin);
    return o.rfind("http://", 0) == 0 && ownHost(o.substr(7), port);
}

// The media type without parameters (`application/json; charset=utf-8`).
bool isJson(const std::string& contentType) {
    std::string type = lowered(contentType.substr(0, contentType.find(';')));
    type.erase(std::remove_if(type.begin(), type.end(), [](unsigned char c) { return std::isspace(c); }), type.end());
    return type == "application/json";
}

}  // namespace

std::optional<Rejection> rejectRequest(const RequestHeaders& r, int port) {
    if (!ownHost(r.host, port))
        return Rejection{403, "the Host header must be 127.0.0.1:" + std::to_string(port) + " or localhost:" +
                                  std::to_string(port) + " (got `" + r.host + "`)"};
    const bool api = r.path.rfind("/api/", 0) == 0;
    if (api && r.hasOrigin && !ownOrigin(r.origin, port))
        return Rejection{403, "API calls are accepted from the studio's own page only (Origin `" + r.origin + "`)"};
    const bool write = r.method != "GET" && r.method != "HEAD";
    if (api && write && !isJson(r.contentType))
        return Rejection{403, "API writes need Content-Type: application/json (got `" + r.contentType + "`)"};
    return std::nullopt;
}

}  // namespace g2d::studio
