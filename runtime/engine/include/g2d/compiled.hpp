#pragma once
// What generated grammar code includes: the engine's public headers and a
// few helpers that keep generated code short. Generated code calls the same
// runtime functions as the interpreter, so both compute the same bits.
// A generated program with a main (`g2d build`) also includes
// g2d/run_options.hpp, of the g2d_run library; a grammar compiled for
// embedding (g2d_add_grammar) needs the engine alone.
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "g2d/builtins.hpp"
#include "g2d/daughter_faces.hpp"
#include "g2d/deadline.hpp"
#include "g2d/derivation.hpp"
#include "g2d/draw_items.hpp"
#include "g2d/element_facts.hpp"
#include "g2d/face_split.hpp"
#include "g2d/obj_writer.hpp"
#include "g2d/grammar_run.hpp"
#include "g2d/graph.hpp"
#include "g2d/grow_array.hpp"
#include "g2d/json_writer.hpp"
#include "g2d/ops.hpp"
#include "g2d/placement.hpp"
#include "g2d/prefetch.hpp"
#include "g2d/rng.hpp"
#include "g2d/svg_writer.hpp"
#include "g2d/value.hpp"
#include "g2d/vec_math.hpp"

namespace g2d::rt::compiled {

// A run-time error at a known place of the grammar's source (an index into
// the generated program's table of places).
class PlacedError : public std::runtime_error {
public:
    PlacedError(int place, const std::string& message) : std::runtime_error(message), place(place) {}
    int place;
};

struct Place {
    const char* file;
    unsigned line, col, endCol;
    const char* lineText;
};

// str() and format's holes, typed: the runtime's toString and formatHole.
template <class T>
std::string str(const T& v) {
    return toString(Value{v});
}
template <class T>
FormatHole hole(const T& v) {
    return formatHole(Value{v});
}

// A growable array that does not copy itself as it grows when T is plain
// data (GrowArray), a std::vector otherwise.
template <class T>
using GrowableArray = std::conditional_t<std::is_trivially_copyable_v<T>, GrowArray<T>, std::vector<T>>;

// Typed attribute arrays: an element's slot indexes its kind's array (one
// that grows without copying when the attributes are plain numbers).
template <class T>
class Store {
public:
    std::uint32_t add(T value) {
        items_.push_back(std::move(value));
        return static_cast<std::uint32_t>(items_.size() - 1);
    }
    T& operator[](std::uint32_t slot) { return items_[slot]; }
    const T& operator[](std::uint32_t slot) const { return items_[slot]; }
    void prefetch(std::uint32_t slot) const {
        if (slot < items_.size()) prefetchRecordLines(&items_[slot], sizeof(T));
    }
    void clear() { items_.clear(); }

private:
    GrowableArray<T> items_;
};

}  // namespace g2d::rt::compiled
