#include "g2d/command_list.hpp"

#include "g2d/ops.hpp"

namespace g2d::rt {

namespace {

// Entries [from, to) of the list, each repeat's body as often as its count.
bool walk(const std::vector<SequenceEntry>& list, const std::vector<long long>& counts, std::size_t from, std::size_t to,
          const std::function<bool(const SequenceEntry&)>& run) {
    for (std::size_t i = from; i < to; ++i) {
        const SequenceEntry& e = list[i];
        if (e.kind != SequenceEntry::Repeat) {
            if (!run(e)) return false;
            continue;
        }
        for (long long k = 0; k < counts.at(e.index); ++k)
            if (!walk(list, counts, i + 1, i + 1 + e.body, run)) return false;
        i += e.body;
    }
    return true;
}

}  // namespace

long long checkedRepeatCount(long long count) {
    if (count < 0) throw OpError("a repeat count cannot be negative (it is " + std::to_string(count) + ")");
    return count;
}

bool forEachCommand(const std::vector<SequenceEntry>& list, const std::vector<long long>& counts,
                    const std::function<bool(const SequenceEntry&)>& run) {
    return walk(list, counts, 0, list.size(), run);
}

}  // namespace g2d::rt
