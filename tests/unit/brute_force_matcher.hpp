#pragma once
// A brute-force matcher for the matching tests: it tries every assignment of
// pattern nodes, then of pattern edges, and knows nothing of search plans,
// anchors or indexes. Host and pattern use two node kinds (0: A, 1: B; -1 in
// a pattern: a wildcard) and two edge kinds (0: E, directed; 1: U, undirected),
// written as g2d source by kindName and edgeText.
#include <cstdint>
#include <functional>
#include <set>
#include <string>
#include <vector>

namespace g2d::test::brute {

struct Edge {
    int kind, src, dst;
};

struct Graph {
    std::vector<int> kinds;
    std::vector<Edge> edges;
};

using MatchIds = std::vector<std::uint32_t>;   // host nodes, then host edges, in pattern order
using Matches = std::set<MatchIds>;

struct Options {
    // `dpo`: two wildcards may bind one host node (typed nodes stay distinct).
    bool identifyWildcards = false;
    // `dpo` deleting this pattern node: its host's degree must equal its
    // pattern degree (a loop counts once in both). -1: none deleted.
    int deletedNode = -1;
    // Conditions on the nodes bound (checked before edges are), and on the
    // whole binding (a negative condition); empty: none.
    std::function<bool(const std::vector<int>& nodes)> nodesHold;
    std::function<bool(const std::vector<int>& nodes, const std::vector<int>& edges)> matchHolds;
};

const char* kindName(int kind);
std::string edgeText(const std::string& a, int kind, const std::string& b);
// Whether host edge h can bind a pattern edge of `kind` from src to dst (host nodes).
bool edgeFits(const Edge& h, int kind, int src, int dst);

Matches matches(const Graph& host, const Graph& pattern, const Options& options = {});

}  // namespace g2d::test::brute
