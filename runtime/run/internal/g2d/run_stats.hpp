#pragma once
// The `--stats` line: one JSON object of a run's counts and counters.
#include <string>

#include "g2d/derivation_result.hpp"
#include "g2d/graph.hpp"

namespace g2d::rt {

std::string runStatsLine(const DerivationResult& result, const Graph& graph, unsigned long long seed, const std::string& stopped);

}  // namespace g2d::rt
