#include "g2d/style_store.hpp"

#include <stdexcept>
#include <string>

namespace g2d::rt {

std::size_t StyleList::size() const {
    std::size_t n = 0;
    for (auto it = begin(); it != end(); ++it) ++n;
    return n;
}

namespace {
[[noreturn]] void tooMany() {
    throw std::length_error("more than " + std::to_string(kMaxStyleProps) + " style properties");
}
}  // namespace

StyleStore::StyleStore(std::vector<std::string> props)
    : names_(std::make_move_iterator(props.begin()), std::make_move_iterator(props.end())) {
    if (names_.size() > kMaxStyleProps) tooMany();
}

StyleProp StyleStore::prop(std::string_view name) {
    for (std::size_t i = 0; i < names_.size(); ++i)
        if (names_[i] == name) return static_cast<StyleProp>(i);
    if (names_.size() >= kMaxStyleProps) tooMany();
    names_.emplace_back(name);
    return static_cast<StyleProp>(names_.size() - 1);
}

void StyleStore::set(std::uint32_t& head, StyleProp p, Value&& v) { entryFor(head, p).value = std::move(v); }

void StyleStore::set(std::uint32_t& head, StyleProp p, const Value& v) { entryFor(head, p).value = v; }

StyleEntry& StyleStore::entryFor(std::uint32_t& head, StyleProp p) {
    std::uint32_t last = kNone;
    for (std::uint32_t i = head; i != kNone; i = at(i).next) {
        if (at(i).prop == p) return at(i);
        last = i;
    }
    std::uint32_t fresh = free_;
    if (fresh != kNone) {
        free_ = at(fresh).next;
    } else {
        if (used_ == kNone) throw std::length_error("more than 4294967294 style overrides");
        fresh = used_++;
        if ((fresh >> kBlockBits) == blocks_.size())
            blocks_.push_back(std::make_unique<StyleEntry[]>(std::size_t{1} << kBlockBits));
    }
    StyleEntry& e = at(fresh);
    e.next = kNone;
    e.prop = p;
    (last == kNone ? head : at(last).next) = fresh;
    return e;
}

void StyleStore::drop(std::uint32_t& head) {
    if (head == kNone) return;
    std::uint32_t last = head;
    while (true) {
        // A long string (an SVG path) is not kept alive by a dead element.
        at(last).value = Value{};
        if (at(last).next == kNone) break;
        last = at(last).next;
    }
    at(last).next = free_;
    free_ = head;
    head = kNone;
}

std::size_t StyleStore::memoryBytes() const {
    return blocks_.size() * ((std::size_t{1} << kBlockBits) * sizeof(StyleEntry) + sizeof(blocks_[0])) +
           names_.size() * sizeof(std::string);
}

}  // namespace g2d::rt
