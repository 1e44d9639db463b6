#pragma once
// Builds the search plan of a pattern (GrGen style): bind the most selective
// element first, then walk incidences, testing each condition as soon as
// every element it reads is bound.
#include <vector>

#include "ir/ir.hpp"

namespace g2d::sema {

// `nodes` and `edges` are numbered from nodeBase and edgeBase (a negative
// condition extends its rule's match: nodes below nodeBase and edges below
// edgeBase are already bound).
// `anchor` >= 0: that node is bound before the search starts.
std::vector<ir::PlanStep> buildSearchPlan(const std::vector<ir::PatternNode>& nodes,
                                          const std::vector<ir::PatternEdge>& edges,
                                          const std::vector<ir::Condition>& conditions, int nodeBase,
                                          int edgeBase, int boundOuterNodes, int anchor = -1);

}  // namespace g2d::sema

namespace g2d::sema {

// Rule::repairRadius of a rule whose match and negative conditions are built.
int repairRadius(const ir::Rule& rule);
// Rule::readsIncidence of a rule whose match and negative conditions are built.
std::vector<ir::IncidenceRead> incidenceReaders(const ir::Rule& rule);
// ir::Rule::readDirections, from its edges, their kinds' directedness
// (`directed`, by kind) and readsIncidence.
std::vector<std::uint8_t> incidenceDirections(const ir::Rule& rule, const std::vector<bool>& directed);
// ir::Rule::newHostAddsNothing, from its edges and readsIncidence.
std::vector<bool> newHostsAddingNothing(const ir::Rule& rule);
// ir::Rule::neededEdgeKinds, for a grammar declaring `edgeKinds` edge kinds.
std::vector<std::vector<int>> edgeKindsNeeded(const ir::Rule& rule, int edgeKinds);

}  // namespace g2d::sema
