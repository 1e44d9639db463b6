#pragma once
// What the studio accepts before routing (it serves a user's files to a
// browser, where any page may send it requests):
// - the Host must be the studio's own loopback name and port, so a page
//   whose name was rebound to 127.0.0.1 (DNS rebinding) is refused;
// - an API call carrying an Origin must come from the studio's own page;
// - an API write (POST, PUT) must say `Content-Type: application/json`,
//   which a cross-site form or simple request cannot send without CORS.
#include <optional>
#include <string>

namespace g2d::studio {

struct Rejection {
    int status = 403;
    std::string reason;
};

struct RequestHeaders {
    std::string method, path, host, origin, contentType;
    bool hasOrigin = false;
};

// Why the request is refused, or nothing. `port` is the studio's.
std::optional<Rejection> rejectRequest(const RequestHeaders& request, int port);

}  // namespace g2d::studio
