#include "lower/command_lists.hpp"

namespace g2d::lower {

namespace {

std::vector<rt::SequenceEntry> entriesOf(const std::vector<ir::SequenceEntry>& list) {
    std::vector<rt::SequenceEntry> out;
    for (const auto& e : list) {
        const rt::SequenceEntry::Kind kind = e.kind == ir::SequenceEntry::Kind::Compound ? rt::SequenceEntry::Compound
                                             : e.kind == ir::SequenceEntry::Kind::Repeat ? rt::SequenceEntry::Repeat
                                                                                         : rt::SequenceEntry::Rule;
        out.push_back(rt::SequenceEntry{kind, static_cast<std::size_t>(e.index), static_cast<std::size_t>(e.body)});
    }
    return out;
}

}  // namespace

std::vector<rt::SequenceEntry> sequenceOf(const ir::Program& prog) { return entriesOf(prog.sequence); }

std::vector<rt::CompoundInfo> compoundsOf(const ir::Program& prog) {
    std::vector<rt::CompoundInfo> out;
    for (const auto& c : prog.compounds)
        out.push_back(rt::CompoundInfo{c.name, static_cast<std::size_t>(c.matchRule), entriesOf(c.entries)});
    return out;
}

}  // namespace g2d::lower
