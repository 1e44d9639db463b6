#include "g2d/text_out.hpp"

#include <charconv>
#include <cmath>

namespace g2d::rt {

TextOut::TextOut() : buf_(new char[kCapacity]) {}

void TextOut::flush() {
    if (used_ == 0) return;
    const std::size_t n = used_;
    used_ = 0;
    drain(buf_.get(), n);
}

void TextOut::spill(std::string_view s) {
    flush();
    if (s.size() >= kCapacity) {
        drain(s.data(), s.size());   // a long piece goes through without a copy
        return;
    }
    std::memcpy(buf_.get(), s.data(), s.size());
    used_ = s.size();
}

char* TextOut::reserve(std::size_t n) {
    if (kCapacity - used_ < n) flush();
    return buf_.get() + used_;
}

void TextOut::number(double x) {
    if (x == 0) return write('0');
    if (std::isnan(x)) return write("nan");
    if (std::isinf(x)) return write(x > 0 ? "inf" : "-inf");
    constexpr std::size_t kLongest = sizeof RecentNumber::text;   // "-1.2345678901234567e-308" and the like
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    RecentNumber& slot = recent_[(bits * 0x9E3779B97F4A7C15ULL) >> (64 - kRecentBits)];
    char* at = reserve(kLongest);
    if (slot.bits == bits && slot.size != 0) {
        std::memcpy(at, slot.text, kLongest);
        used_ += slot.size;
        return;
    }
    const auto size = static_cast<std::size_t>(std::to_chars(at, at + kLongest, x).ptr - at);
    std::memcpy(slot.text, at, kLongest);
    slot.bits = bits;
    slot.size = static_cast<std::uint8_t>(size);
    used_ += size;
}

void TextOut::integer(long long v) {
    constexpr std::size_t kLongest = 24;
    char* at = reserve(kLongest);
    used_ += static_cast<std::size_t>(std::to_chars(at, at + kLongest, v).ptr - at);
}

}  // namespace g2d::rt
