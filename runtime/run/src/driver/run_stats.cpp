#include "g2d/run_stats.hpp"

#include <utility>
#include <vector>

#include "g2d/json_writer.hpp"

namespace g2d::rt {

std::string runStatsLine(const DerivationResult& r, const Graph& g, unsigned long long seed, const std::string& stopped) {
    // In this order; a new counter goes at the end, so readers of the old
    // fields keep working.
    const std::vector<std::pair<const char*, std::string>> fields = {
        {"steps", std::to_string(r.steps)},
        {"nodes", std::to_string(g.nodeCount())},
        {"edges", std::to_string(g.edgeCount())},
        {"faces", std::to_string(g.faceCount())},
        {"seconds", formatNumber(r.seconds)},
        {"seed", std::to_string(seed)},
        {"stopped", jsonString(stopped)},
        {"applications", std::to_string(r.applications)},
        {"lookahead_guesses", std::to_string(r.lookaheadGuesses)},
        {"lookahead_hits", std::to_string(r.lookaheadHits)},
        {"repairs", std::to_string(r.setRepairs)},
        {"repairs_skipped", std::to_string(r.setRepairsSkipped)},
        {"rejected_drawings", std::to_string(r.rejectedDrawings)},
        {"rejected_by_cost", std::to_string(r.rejectedByCost)},
        {"rejected_splits", std::to_string(r.rejectedSplits)},
        {"bends_reduced", std::to_string(r.bendsReduced)},
        {"faces_against_neighbours", std::to_string(r.facesAgainstNeighbours)},
        {"inserts_without_side", std::to_string(r.insertsWithoutSide)},
        {"compounds_without_instances", std::to_string(r.compoundsWithoutInstances)},
        {"rejected_intersections", std::to_string(r.rejectedIntersections)},
    };
    std::string line = "{";
    for (const auto& [name, value] : fields) line += (line.size() > 1 ? ", \"" : "\"") + std::string(name) + "\": " + value;
    return line + "}\n";
}

}  // namespace g2d::rt
