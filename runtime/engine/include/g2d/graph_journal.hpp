#pragma once
// What one application did to the graph's old elements, in order, so that
// it can be undone exactly (G^3's intersection tests, intersection_guard.hpp:
// "the command is not applied"). Graph::beginJournal starts one; while it
// is set, the graph records each change to an element older than the
// journal (a move, a new radius, a rewired edge, a corner put into a face,
// a face removed), with the id capacities at that moment, so that undoing
// removes the new elements made after each change before reverting it: the
// lists threaded through the records (a node's edges and corners, a kind's
// elements) come back in their old order. New elements need no record: ids
// are never reused, so they are the ids from the capacities on.
#include <array>
#include <cstdint>
#include <vector>

#include "g2d/vec_math.hpp"

namespace g2d::rt {

struct GraphJournal {
    // Node, edge and face capacities.
    using Capacities = std::array<std::size_t, 3>;
    enum class Op : std::uint8_t { Node, Edge, Corner, FaceRemoved };
    struct Entry {
        Op op;
        std::uint32_t id;
        Capacities at;
        // Node: its position, z and radius before; Edge: its ends and its
        // places in their lists before (src, dst, prevOut, nextOut, prevIn, nextIn).
        vec2 pos{0, 0};
        double z = 0, radius = 0;
        std::array<std::uint32_t, 6> links{};
    };
    Capacities from{};
    std::vector<Entry> entries;
    // A change it cannot undo (an old element deleted, an old face's
    // corners moved or taken out): the checker keeps `intersect` rules from
    // making one, so this is an internal error if an undo needs it.
    bool lost = false;
};

}  // namespace g2d::rt
