#pragma once
// The pieces of a rule's side: the connected parts of its graph, counting
// the interface nodes (a side's vertices and the host nodes its open
// half-edges lead to). A side of several pieces is several spliced graphs
// (Merrell §5.2, Algorithm 2); matched as it is, its pieces could lie
// anywhere in the output, so the written rule asks them to lie as near each
// other as the other side's drawing can bring them (lower::nearJoin then
// searches them there).
#include <string>
#include <vector>

#include "infer/labelled_example.hpp"
#include "infer/rule_sides.hpp"

namespace g2d::infer {

// Per node of the side (its vertices, then interface nodes 0 … interface-1): its piece, numbered from 0.
std::vector<int> sidePieces(const RuleSide& side, int interface);
int pieceCount(const RuleSide& side, int interface);

// Whether applying the rule in either direction keeps a connected graph
// connected: each side is one piece.
bool keepsConnected(const RuleSides& sides);

// The conditions that keep a match of `match` (a side of several pieces)
// local: for each piece after the first, `where distance(xB.pos, xA.pos + C) <= D
// and distance(xA.pos, xB.pos - C) <= D;` with xA an interface node of the
// first piece and xB one of that piece: the other side, `daughter`, draws
// the path between them as C (each edge's direction times its middle
// length) give or take D (half of each length range), along the path that
// allows the least.
// Empty for a side of one piece.
std::vector<std::string> nearnessConditions(const LabelledExample& ex, const RuleSide& match, const RuleSide& daughter, int interface);

}  // namespace g2d::infer
