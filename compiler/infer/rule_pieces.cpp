#include "infer/rule_pieces.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>

namespace g2d::infer {
namespace {

int nodeOf(const RuleSide& side, int end) { return end >= 0 ? end : static_cast<int>(side.primitive.size()) + (-1 - end); }

int find(std::vector<int>& parent, int i) {
    while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    return i;
}

// The longest drawn distance along the daughter's paths from interface node a to each node (Dijkstra on longest lengths).
std::vector<double> reach(const LabelledExample& ex, const RuleSide& side, int interface, int from) {
    const int n = static_cast<int>(side.primitive.size()) + interface;
    std::vector<std::vector<std::pair<int, double>>> next(static_cast<std::size_t>(n));
    for (const SideEdge& e : side.edges) {
        const double len = ex.labels[static_cast<std::size_t>(e.label)].maxLength;
        const int a = nodeOf(side, e.from), b = nodeOf(side, e.to);
        next[static_cast<std::size_t>(a)].push_back({b, len});
        next[static_cast<std::size_t>(b)].push_back({a, len});
    }
    std::vector<double> dist(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
    dist[static_cast<std::size_t>(from)] = 0;
    open.push({0, from});
    while (!open.empty()) {
        const auto [d, v] = open.top();
        open.pop();
        if (d > dist[static_cast<std::size_t>(v)]) continue;
        for (const auto& [w, len] : next[static_cast<std::size_t>(v)])
            if (d + len < dist[static_cast<std::size_t>(w)]) {
                dist[static_cast<std::size_t>(w)] = d + len;
                open.push({d + len, w});
            }
    }
    return dist;
}

// The shortest text that reads back as the same number, rounded up a little (a bound, never below the exact one).
std::string bound(double v) {
    char buf[64];
    const double up = std::ceil(v * 1e6) / 1e6;
    const auto r = std::to_chars(buf, buf + sizeof buf, up);
    return std::string(buf, r.ptr);
}

}  // namespace

std::vector<int> sidePieces(const RuleSide& side, int interface) {
    const int n = static_cast<int>(side.primitive.size()) + interface;
    std::vector<int> parent(static_cast<std::size_t>(n));
    std::iota(parent.begin(), parent.end(), 0);
    for (const SideEdge& e : side.edges) parent[static_cast<std::size_t>(find(parent, nodeOf(side, e.from)))] = find(parent, nodeOf(side, e.to));
    std::vector<int> piece(static_cast<std::size_t>(n), -1), number(static_cast<std::size_t>(n), -1);
    int pieces = 0;
    for (int v = 0; v < n; ++v) {
        const int root = find(parent, v);
        if (number[static_cast<std::size_t>(root)] < 0) number[static_cast<std::size_t>(root)] = pieces++;
        piece[static_cast<std::size_t>(v)] = number[static_cast<std::size_t>(root)];
    }
    return piece;
}

int pieceCount(const RuleSide& side, int interface) {
    int most = -1;
    for (int p : sidePieces(side, interface)) most = std::max(most, p);
    return most + 1;
}

bool keepsConnected(const RuleSides& sides) {
    return pieceCount(sides.left, sides.interface) <= 1 && pieceCount(sides.right, sides.interface) <= 1;
}

std::vector<std::string> nearnessConditions(const LabelledExample& ex, const RuleSide& match, const RuleSide& daughter, int interface) {
    std::vector<std::string> out;
    const std::vector<int> piece = sidePieces(match, interface);
    const int base = static_cast<int>(match.primitive.size());
    // Each piece's first interface node, pieces in the order their first one comes.
    std::vector<int> first, seen;
    for (int k = 0; k < interface; ++k) {
        const int p = piece[static_cast<std::size_t>(base + k)];
        if (std::find(seen.begin(), seen.end(), p) != seen.end()) continue;
        seen.push_back(p);
        first.push_back(k);
    }
    if (first.size() <= 1) return out;
    const std::vector<double> dist = reach(ex, daughter, interface, static_cast<int>(daughter.primitive.size()) + first[0]);
    for (std::size_t p = 1; p < first.size(); ++p) {
        const double d = dist[daughter.primitive.size() + static_cast<std::size_t>(first[p])];
        if (!std::isfinite(d)) continue;   // the daughter does not join them either
        out.push_back("where distance(x" + std::to_string(first[0]) + ".pos, x" + std::to_string(first[p]) + ".pos) <= " + bound(d) + ";");
    }
    return out;
}

}  // namespace g2d::infer
