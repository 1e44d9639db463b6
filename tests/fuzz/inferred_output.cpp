#include "inferred_output.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace g2d::fuzz {

namespace {

// The number in a kind's name: P3 -> 3, L0 -> 0.
int kindNumber(const ir::Program& program, int kind) {
    return std::stoi(program.kinds[static_cast<std::size_t>(kind)].name.substr(1));
}

}  // namespace

InferredOutput measureInferredOutput(const infer::LabelledExample& ex, const ir::Program& program, const rt::Graph& graph) {
    InferredOutput out;
    std::map<rt::NodeId, rt::NodeId> parent;
    auto find = [&](rt::NodeId n) {
        while (parent[n] != n) n = parent[n] = parent[parent[n]];
        return n;
    };
    for (rt::NodeId n : graph.allNodes()) parent[n] = n;
    for (rt::NodeId n : graph.allNodes()) {
        ++out.vertices;
        std::vector<int> halves;
        for (rt::EdgeId e : graph.incident(n)) {
            halves.push_back(infer::halfLabel(kindNumber(program, graph.edgeKind(e)), graph.target(e) == n));
            parent[find(graph.source(e))] = find(graph.target(e));
        }
        std::vector<int> want = ex.primitives[static_cast<std::size_t>(kindNumber(program, graph.nodeKind(n)))].halves;
        std::sort(halves.begin(), halves.end());
        std::sort(want.begin(), want.end());
        if (halves != want && out.dissimilar < 0) out.dissimilar = static_cast<int>(n);
    }
    for (const auto& [n, p] : parent) out.pieces += n == p ? 1 : 0;
    return out;
}

}  // namespace g2d::fuzz
