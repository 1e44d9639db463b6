#pragma once
// The structured fuzz targets' view of libFuzzer's bytes: small numbers and
// strings taken from the front, zeros once they run out (so every input,
// however short, makes a case, and a longer one only adds to it).
#include <cstddef>
#include <cstdint>
#include <string>

namespace g2d::fuzz {

class ByteSource {
public:
    ByteSource(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    bool empty() const { return at_ >= size_; }
    std::uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
    // In [0, n) (n >= 1).
    std::uint32_t below(std::uint32_t n) {
        const std::uint32_t v = static_cast<std::uint32_t>(byte()) << 8 | byte();
        return v % n;
    }
    std::uint32_t word() {
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v = v << 8 | byte();
        return v;
    }
    // Up to `max` bytes, as many as the next byte says.
    std::string text(std::size_t max) {
        std::size_t n = byte();
        if (n > max) n = max;
        std::string out;
        while (n-- > 0 && !empty()) out += static_cast<char>(byte());
        return out;
    }
    std::string rest() {
        std::string out(reinterpret_cast<const char*>(data_ + (at_ < size_ ? at_ : size_)), at_ < size_ ? size_ - at_ : 0);
        at_ = size_;
        return out;
    }

private:
    const std::uint8_t* data_;
    std::size_t size_, at_ = 0;
};

}  // namespace g2d::fuzz
