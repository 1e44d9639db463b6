#include "g2d/seed_rows.hpp"

#include <cerrno>
#include <cstdio>
#include <unistd.h>

#include "g2d/json_writer.hpp"
#include "g2d/value.hpp"

namespace g2d::rt {

namespace {

// The fixed part of a row on the pipe; the two texts follow.
struct RowHeader {
    std::uint64_t seed;
    std::int32_t status;
    std::int64_t steps;
    std::uint64_t elements, faces;
    double seconds;
    std::uint32_t stoppedSize, messagesSize, stagedCount;
};

constexpr std::uint32_t kMaxStaged = 16;   // a run writes at most eight outputs

constexpr std::size_t kMaxText = 1 << 20;   // a sane bound for reading: rows come from our own workers

void appendText(std::string& buffer, const std::string& text) {
    const auto size = static_cast<std::uint32_t>(text.size());
    buffer.append(reinterpret_cast<const char*>(&size), sizeof size);
    buffer += text;
}

bool readText(int fd, std::string& text) {
    std::uint32_t size = 0;
    if (!readFully(fd, &size, sizeof size) || size > kMaxText) return false;
    text.assign(size, '\0');
    return readFully(fd, text.data(), size);
}

}  // namespace

bool writeFully(int fd, const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t n = ::write(fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        size -= static_cast<std::size_t>(n);
    }
    return true;
}

bool readFully(int fd, void* data, std::size_t size) {
    char* p = static_cast<char*>(data);
    while (size > 0) {
        const ssize_t n = ::read(fd, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        size -= static_cast<std::size_t>(n);
    }
    return true;
}

bool writeRow(int fd, const SeedRow& row) {
    const std::string stopped = row.stopped.substr(0, kMaxText), messages = row.messages.substr(0, kMaxText);
    const RowHeader h{row.seed, row.status, row.steps, row.elements, row.faces, row.seconds,
                      static_cast<std::uint32_t>(stopped.size()), static_cast<std::uint32_t>(messages.size()),
                      static_cast<std::uint32_t>(row.staged.size())};
    std::string buffer(reinterpret_cast<const char*>(&h), sizeof h);
    buffer += stopped;
    buffer += messages;
    for (const auto& f : row.staged)
        for (const std::string* text : {&f.temp, &f.target, &f.path}) appendText(buffer, *text);
    return writeFully(fd, buffer.data(), buffer.size());
}

std::optional<SeedRow> readRow(int fd) {
    RowHeader h{};
    if (!readFully(fd, &h, sizeof h) || h.stoppedSize > kMaxText || h.messagesSize > kMaxText || h.stagedCount > kMaxStaged)
        return std::nullopt;
    SeedRow row{h.seed, h.status, h.steps, h.elements, h.faces, h.seconds, std::string(h.stoppedSize, '\0'),
                std::string(h.messagesSize, '\0'), std::vector<StagedFile>(h.stagedCount)};
    if (!readFully(fd, row.stopped.data(), row.stopped.size()) || !readFully(fd, row.messages.data(), row.messages.size()))
        return std::nullopt;
    for (auto& f : row.staged)
        for (std::string* text : {&f.temp, &f.target, &f.path})
            if (!readText(fd, *text)) return std::nullopt;
    return row;
}

std::string summaryLine(const SeedRow& row) {
    std::string line = "{\"seed\": " + std::to_string(row.seed) + ", \"steps\": " + std::to_string(row.steps) +
                       ", \"elements\": " + std::to_string(row.elements) +
                       ", \"faces\": " + std::to_string(row.faces) + ", \"seconds\": " + formatFixed(row.seconds, 4) +
                       ", \"stopped\": " + jsonString(row.stopped);
    if (row.status != 0) {
        const std::string first = row.messages.substr(0, row.messages.find('\n'));
        line += ", \"error\": " + jsonString(first.empty() ? "failed" : first);
    }
    return line + "}\n";
}

}  // namespace g2d::rt
