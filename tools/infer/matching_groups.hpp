#pragma once
// Algorithm 2 (§5.3): which simpler graphs, spliced together, have the same
// boundary string as a graph L. A candidate R embeds in L's boundary S when
// its half-edges appear in S in order with the same winding differences;
// the runs of S between them (the gaps) are closed into boundaries of their
// own and matched recursively. Matching winding differences is the paper's
// "match ∂R with ∨ⁿ∂L∧ⁿ" and "∂L_i∧" made exact (docs/research/merrell-digest.md §4.4).
#include <vector>

#include "infer/grammar_inference.hpp"

namespace g2d::infer {

struct GroupEntry {
    int half = 0;
    int wind = 0;
    int origin = 0;   // the entry of L's boundary it stands for
};

// Candidates are tried in the order given. On success `pieces` holds the
// groups and true is returned.
bool findMatchingGroups(const std::vector<GroupEntry>& boundary, const std::vector<const HierarchyEntry*>& candidates,
                        const std::vector<int>& candidateIndex, std::vector<RulePiece>& pieces);

}  // namespace g2d::infer
