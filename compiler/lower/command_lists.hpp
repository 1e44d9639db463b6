#pragma once
// The grammar's command lists (`sequence`, compounds) as the runtime reads
// them (rt::SequenceEntry, rt::CompoundInfo): both back ends give these.
#include <vector>

#include "g2d/command_list.hpp"
#include "ir/ir.hpp"

namespace g2d::lower {

std::vector<rt::SequenceEntry> sequenceOf(const ir::Program& prog);
std::vector<rt::CompoundInfo> compoundsOf(const ir::Program& prog);

}  // namespace g2d::lower
