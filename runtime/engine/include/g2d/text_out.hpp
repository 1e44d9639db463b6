#pragma once
// Text written in pieces through a fixed-size buffer, so that an output of
// any size costs the same memory: the writers (SVG, JSON, OBJ) append to a
// TextOut, which hands full buffers to its sink (a file, or a string for the
// small pages that embed a drawing). Numbers are formatted straight into the
// buffer, with the same text as formatNumber.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>

namespace g2d::rt {

class TextOut {
public:
    TextOut(const TextOut&) = delete;
    TextOut& operator=(const TextOut&) = delete;

    void write(std::string_view s) {
        if (s.size() <= kCapacity - used_) {
            std::memcpy(buf_.get() + used_, s.data(), s.size());
            used_ += s.size();
        } else {
            spill(s);
        }
    }
    void write(char c) {
        if (used_ == kCapacity) flush();
        buf_[used_++] = c;
    }
    // As formatNumber(x): the shortest round-trip decimal, "0" for ±0.
    void number(double x);
    void integer(long long v);
    // Hands the buffered text to the sink.
    void flush();

protected:
    TextOut();
    virtual ~TextOut() = default;
    virtual void drain(const char* data, std::size_t size) = 0;

private:
    static constexpr std::size_t kCapacity = std::size_t{1} << 16;
    void spill(std::string_view s);
    char* reserve(std::size_t n);   // room for n more characters

    std::unique_ptr<char[]> buf_;
    std::size_t used_ = 0;
    // The texts of recent numbers by their bits: drawings repeat them (an
    // edge starts where the last one ended, a width recurs), and the shortest
    // round-trip text costs more than a lookup.
    struct RecentNumber {
        std::uint64_t bits = 0;
        std::uint8_t size = 0;   // 0: empty
        char text[31];
    };
    static constexpr int kRecentBits = 4;
    RecentNumber recent_[1 << kRecentBits];
};

// Collects the text in memory (the trace page embeds the SVG).
class StringOut final : public TextOut {
public:
    StringOut() = default;
    // The text so far (flushes first).
    std::string& text() {
        flush();
        return text_;
    }

private:
    void drain(const char* data, std::size_t size) override { text_.append(data, size); }
    std::string text_;
};

}  // namespace g2d::rt
