#include "studio/studio_routes.hpp"

#include <httplib.h>

#include <fstream>
#include <sstream>

#include "studio/api_reply.hpp"
#include "studio/edited_file.hpp"
#include "studio/file_watch.hpp"
#include "studio/grammar_jobs.hpp"
#include "studio/request_guard.hpp"
#include "studio/studio_page.hpp"

namespace g2d::studio {

namespace {

void send(httplib::Response& res, const ApiReply& reply) {
    res.status = reply.status;
    res.set_header("Cache-Control", "no-store");
    res.set_content(reply.body, reply.mediaType);
}

// The body as a JSON object, or a 400 already sent.
std::optional<nlohmann::json> jsonBody(const httplib::Request& req, httplib::Response& res) {
    auto body = nlohmann::json::parse(req.body, nullptr, false);
    if (body.is_discarded() || !body.is_object()) {
        send(res, errorReply(400, "the request body must be a JSON object"));
        return std::nullopt;
    }
    return body;
}

constexpr std::uint64_t kMaxSheetSeeds = 64;

std::string sseEvent(const char* name, const FileChange& change) {
    return std::string("event: ") + name + "\ndata: " + nlohmann::json{{"version", change.version}}.dump() + "\n\n";
}

}  // namespace

void addStudioRoutes(httplib::Server& server, StudioParts parts) {
    server.set_payload_max_length(kMaxRequestBytes);
    // No other site may embed an answer as a script, image or style (a GET without CORS), nor
    // may the browser guess a type the studio did not say.
    server.set_default_headers({{"Cross-Origin-Resource-Policy", "same-origin"}, {"X-Content-Type-Options", "nosniff"}});
    server.set_pre_routing_handler([parts](const httplib::Request& req, httplib::Response& res) {
        RequestHeaders headers{req.method, req.path, req.get_header_value("Host"), req.get_header_value("Origin"),
                               req.get_header_value("Content-Type"), req.has_header("Origin")};
        if (auto no = rejectRequest(headers, parts.port)) {
            send(res, errorReply(no->status, no->reason));
            return httplib::Server::HandlerResponse::Handled;
        }
        return httplib::Server::HandlerResponse::Unhandled;
    });

    server.Get("/", [](const httplib::Request&, httplib::Response& res) {
        res.set_header("Content-Security-Policy", studioPagePolicy());
        res.set_content(studioPage(), "text/html; charset=utf-8");   // 5 kB: compressed or not, it makes no odds
    });
    server.Get("/studio.js", [](const httplib::Request&, httplib::Response& res) {
        res.set_content(studioScript(), "application/javascript; charset=utf-8");   // not compressed (api_reply.hpp)
    });

    server.Get("/api/file", [parts](const httplib::Request&, httplib::Response& res) {
        const FileState state = parts.file.read();
        send(res, jsonReply(200, {{"path", parts.file.path()}, {"exists", state.exists}, {"text", state.text},
                                  {"version", state.version}}));
    });
    server.Put("/api/file", [parts](const httplib::Request& req, httplib::Response& res) {
        auto body = jsonBody(req, res);
        if (!body) return;
        if (!(*body)["text"].is_string() || !(*body)["version"].is_string())
            return send(res, errorReply(400, "expected {\"text\": …, \"version\": …} (the version the text was loaded at)"));
        const SaveResult saved = parts.file.save((*body)["text"], (*body)["version"]);
        using Outcome = SaveResult::Outcome;
        if (saved.outcome == Outcome::Saved) return send(res, jsonReply(200, {{"status", "saved"}, {"version", saved.version}}));
        const int status = saved.outcome == Outcome::Stale ? 409 : saved.outcome == Outcome::NoFile ? 403 : 500;
        send(res, jsonReply(status, {{"status", "error"}, {"message", saved.error}, {"version", saved.version}}));
    });
    server.Get("/api/imports", [parts](const httplib::Request&, httplib::Response& res) { send(res, parts.jobs.imports()); });
    server.Post("/api/check", [parts](const httplib::Request& req, httplib::Response& res) {
        auto body = jsonBody(req, res);
        if (!body) return;
        if (!(*body)["text"].is_string()) return send(res, errorReply(400, "expected {\"text\": …}"));
        send(res, parts.jobs.check((*body)["text"]));
    });
    // The language server's completion at {"text", "line" (1-based), "character" (0-based, UTF-16)}.
    server.Post("/api/complete", [parts](const httplib::Request& req, httplib::Response& res) {
        auto body = jsonBody(req, res);
        if (!body) return;
        const auto &text = (*body)["text"], &line = (*body)["line"], &character = (*body)["character"];
        if (!text.is_string() || !line.is_number_unsigned() || !character.is_number_unsigned() ||
            line.get<std::uint64_t>() > UINT32_MAX || character.get<std::uint64_t>() > UINT32_MAX)
            return send(res, errorReply(400, "expected {\"text\": …, \"line\": N, \"character\": N}"));
        send(res, parts.jobs.complete(text, line.get<std::uint32_t>(), character.get<std::uint32_t>()));
    });
    server.Post("/api/run", [parts](const httplib::Request& req, httplib::Response& res) {
        auto body = jsonBody(req, res);
        if (!body) return;
        std::string why;
        auto input = runInputOf(*body, why);
        if (!input) return send(res, errorReply(400, why));
        send(res, parts.jobs.run(*input));
    });
    // A file to download, as `g2d run` writes it: {…the run's fields, "format": "svg" | "png" | …}.
    server.Post("/api/export", [parts](const httplib::Request& req, httplib::Response& res) {
        auto body = jsonBody(req, res);
        if (!body) return;
        std::string why;
        auto input = runInputOf(*body, why);
        if (!input) return send(res, errorReply(400, why));
        auto format = exportFormatOf(body->value("format", ""));
        if (!format) return send(res, errorReply(400, "\"format\" must be one of svg, png, json, obj, mtl, glb"));
        send(res, parts.jobs.exportFile(*input, *format));
    });
    // Small pictures of the grammar for seeds first…first+count-1: {…the run's fields, "first", "count", "width"}.
    server.Post("/api/seeds", [parts](const httplib::Request& req, httplib::Response& res) {
        auto body = jsonBody(req, res);
        if (!body) return;
        std::string why;
        auto input = runInputOf(*body, why);
        if (!input) return send(res, errorReply(400, why));
        const auto& first = (*body)["first"];
        const auto& count = (*body)["count"];
        const auto& width = (*body)["width"];
        if (!first.is_number_unsigned()) return send(res, errorReply(400, "\"first\" must be a seed: a whole number, 0 or more"));
        if (!count.is_number_unsigned() || count.get<std::uint64_t>() < 1 || count.get<std::uint64_t>() > kMaxSheetSeeds)
            return send(res, errorReply(400, "\"count\" must be from 1 to " + std::to_string(kMaxSheetSeeds)));
        if (!width.is_number_unsigned() || width.get<std::uint64_t>() < 16 || width.get<std::uint64_t>() > 1024)
            return send(res, errorReply(400, "\"width\" must be from 16 to 1024 pixels"));
        send(res, parts.jobs.seeds(*input, first.get<std::uint64_t>(), int(count.get<std::uint64_t>()), int(width.get<std::uint64_t>())));
    });
    server.Post("/api/infer", [parts](const httplib::Request& req, httplib::Response& res) {
        auto body = jsonBody(req, res);
        if (!body) return;
        std::string why;
        auto input = inferInputOf(*body, why);
        if (!input) return send(res, errorReply(400, why));
        send(res, parts.jobs.infer(*input));
    });
    // An image file the page's SVG links (image_shelf.hpp): only those the runs gave an address.
    server.Get(R"(/api/image/(\d{1,9}))", [parts](const httplib::Request& req, httplib::Response& res) {
        const auto image = parts.jobs.images().image(std::stoul(req.matches[1].str()));
        std::ifstream in(image ? image->path : std::string(), std::ios::binary);
        if (!image || !in) return send(res, errorReply(404, "no such image"));
        std::ostringstream bytes;
        bytes << in.rdbuf();
        res.set_header("Cache-Control", "no-cache");
        res.set_content(bytes.str(), image->mediaType);
    });
    server.Get("/api/events", [parts](const httplib::Request&, httplib::Response& res) {
        res.set_header("Cache-Control", "no-store");
        res.set_chunked_content_provider(
            "text/event-stream", [parts, seen = parts.watch.latest(), sent = false](size_t, httplib::DataSink& sink) mutable {
                if (!sent) {   // the version now (the watch may not have looked yet), so a page knows where it starts
                    sent = true;
                    const std::string hello = sseEvent("hello", {seen.number, parts.file.read().version});
                    return sink.write(hello.data(), hello.size());
                }
                auto change = parts.watch.next(seen.number, std::chrono::seconds(10));
                if (parts.watch.stopped()) return false;
                // A comment line keeps the connection alive (and finds a closed one).
                const std::string text = change ? sseEvent("file", *change) : std::string(": idle\n\n");
                if (change) seen = *change;
                return sink.write(text.data(), text.size());
            });
    });
}

}  // namespace g2d::studio
