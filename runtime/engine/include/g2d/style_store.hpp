#pragma once
// Per-element style overrides (`style.fill = ...` in a daughter), for every
// element class of one graph.
//
// Property names are interned: a program numbers the properties it sets
// (ir::Program::styleProps) and the graph starts with them in that order, so
// generated code passes a constant and the interpreter an index, never a
// string. An element's overrides are a chain through one pooled array,
// in the order each property was first set (the order they are written
// out); a removed element's chain returns to a free list. Setting a style
// compares small integers and allocates nothing once the pool is warm. The
// pool grows by blocks, so entries never move (relocating a growing vector
// of them cost more than the settings themselves).
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "g2d/value.hpp"

namespace g2d::rt {

using StyleProp = std::uint16_t;
// How many different properties one graph numbers (sema rejects more).
inline constexpr std::size_t kMaxStyleProps = 65535;

struct StyleEntry {
    Value value;
    std::uint32_t next;
    StyleProp prop;
};

class StyleStore;

// One element's overrides, in the order first set. Valid until the next
// style is set on any element.
class StyleList {
public:
    class iterator {
    public:
        iterator(const StyleStore* store, std::uint32_t at) : store_(store), at_(at) {}
        inline const StyleEntry& operator*() const;
        const StyleEntry* operator->() const { return &**this; }
        iterator& operator++() {
            at_ = (**this).next;
            return *this;
        }
        bool operator==(const iterator& o) const { return at_ == o.at_; }
        bool operator!=(const iterator& o) const { return at_ != o.at_; }

    private:
        const StyleStore* store_;
        std::uint32_t at_;
    };
    static constexpr std::uint32_t kEnd = 0xffffffffu;
    StyleList(const StyleStore* store, std::uint32_t head) : store_(store), head_(head) {}
    iterator begin() const { return iterator(store_, head_); }
    iterator end() const { return iterator(store_, kEnd); }
    bool empty() const { return head_ == kEnd; }
    std::size_t size() const;

private:
    const StyleStore* store_;
    std::uint32_t head_;
};

class StyleStore {
public:
    static constexpr std::uint32_t kNone = StyleList::kEnd;   // an element without overrides

    explicit StyleStore(std::vector<std::string> props = {});

    // The number of a property name, numbering a new name after the others.
    // (A linear search: for setting up and for tests, not for a rewrite.)
    StyleProp prop(std::string_view name);
    const std::string& name(StyleProp p) const { return names_[p]; }
    std::vector<std::string> names() const { return {names_.begin(), names_.end()}; }

    // `head` is an element's chain (kNone for none), kept by the caller.
    void set(std::uint32_t& head, StyleProp p, Value&& v);
    void set(std::uint32_t& head, StyleProp p, const Value& v);   // copied in place (a constant of generated code)
    void drop(std::uint32_t& head);   // the chain goes to the free list
    StyleList list(std::uint32_t head) const { return StyleList(this, head); }
    const StyleEntry& entry(std::uint32_t i) const { return blocks_[i >> kBlockBits][i & kBlockMask]; }

    std::size_t memoryBytes() const;

private:
    // The override of `p` in the chain at `head`, appended (its value
    // left as it was) if the chain has none.
    StyleEntry& entryFor(std::uint32_t& head, StyleProp p);
    // Blocks of 64 entries (3 KiB): a small grammar's overrides touch few
    // fresh pages (every entry of a block is constructed when it is made).
    static constexpr unsigned kBlockBits = 6;
    static constexpr std::uint32_t kBlockMask = (1u << kBlockBits) - 1;
    StyleEntry& at(std::uint32_t i) { return blocks_[i >> kBlockBits][i & kBlockMask]; }

    std::deque<std::string> names_;   // a deque: drawn items keep views of the names as more are added
    std::vector<std::unique_ptr<StyleEntry[]>> blocks_;
    std::uint32_t used_ = 0;   // entries ever taken; below it, free or in a chain
    std::uint32_t free_ = kNone;
};

const StyleEntry& StyleList::iterator::operator*() const { return store_->entry(at_); }

}  // namespace g2d::rt
