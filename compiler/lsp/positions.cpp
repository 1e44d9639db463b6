#include "lsp/positions.hpp"

#include <cctype>
#include <filesystem>
#include <vector>

namespace g2d::lsp {

namespace {

// Byte offsets of each code point's start, and its UTF-16 width.
struct CodePoint {
    std::size_t byte;
    std::uint32_t units;
};

std::vector<CodePoint> codePoints(const std::string& line) {
    std::vector<CodePoint> out;
    for (std::size_t i = 0; i < line.size();) {
        const auto c = static_cast<unsigned char>(line[i]);
        const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 1;
        out.push_back(CodePoint{i, n == 4 ? 2u : 1u});
        i += n;
    }
    return out;
}

bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

std::uint32_t utf16Offset(const std::string& line, std::uint32_t col) {
    const auto points = codePoints(line);
    std::uint32_t units = 0;
    for (std::size_t i = 0; i + 1 < col && i < points.size(); ++i) units += points[i].units;
    if (col > points.size() + 1) units += col - static_cast<std::uint32_t>(points.size()) - 1;
    return units;
}

std::uint32_t codePointColumn(const std::string& line, std::uint32_t character) {
    const auto points = codePoints(line);
    std::uint32_t units = 0, col = 1;
    for (const auto& p : points) {
        if (units >= character) break;
        units += p.units;
        ++col;
    }
    return col;
}

std::size_t byteOffset(const std::string& text, std::uint32_t line, std::uint32_t character) {
    std::size_t start = 0;
    for (std::uint32_t l = 0; l < line; ++l) {
        const std::size_t newline = text.find('\n', start);
        if (newline == std::string::npos) return text.size();
        start = newline + 1;
    }
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (end > start && text[end - 1] == '\r') --end;
    std::uint32_t units = 0;
    for (const CodePoint& p : codePoints(text.substr(start, end - start))) {
        if (units + p.units > character) return start + p.byte;
        units += p.units;
    }
    return end;
}

std::string identifierAt(const std::string& line, std::uint32_t col, std::uint32_t* start) {
    // Identifiers are ASCII, so code-point columns of an ASCII prefix are bytes.
    const auto points = codePoints(line);
    if (points.empty()) return "";
    std::size_t at = col > 0 ? col - 1 : 0;
    if (at >= points.size() || !isIdentChar(line[points[at].byte])) {
        if (at == 0 || at - 1 >= points.size() || !isIdentChar(line[points[at - 1].byte])) return "";
        --at;  // the cursor is just after the identifier
    }
    std::size_t b = at, e = at;
    while (b > 0 && points[b - 1].byte + 1 == points[b].byte && isIdentChar(line[points[b - 1].byte])) --b;
    while (e + 1 < points.size() && isIdentChar(line[points[e + 1].byte])) ++e;
    if (std::isdigit(static_cast<unsigned char>(line[points[b].byte]))) return "";
    if (start) *start = static_cast<std::uint32_t>(b + 1);
    return line.substr(points[b].byte, points[e].byte + 1 - points[b].byte);
}

std::string pathToUri(const std::string& path) {
    std::error_code ec;
    const std::string absolute = std::filesystem::absolute(path, ec).lexically_normal().string();
    std::string out = "file://";
    static const char* hex = "0123456789ABCDEF";
    for (unsigned char c : ec ? path : absolute) {
        if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
            out += static_cast<char>(c);
        } else {
            out += '%';
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out;
}

std::string uriToPath(const std::string& uri) {
    std::string rest = uri.rfind("file://", 0) == 0 ? uri.substr(7) : uri;
    std::string out;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] == '%' && i + 2 < rest.size() && std::isxdigit(static_cast<unsigned char>(rest[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(rest[i + 2]))) {
            out += static_cast<char>(std::stoi(rest.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += rest[i];
        }
    }
    return out;
}

}  // namespace g2d::lsp
